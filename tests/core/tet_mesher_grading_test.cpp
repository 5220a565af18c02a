#include <gtest/gtest.h>

#include "core/error.h"
#include "core/mesh/tet_quality.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"

namespace viscera::core {
namespace {

/// Mean edge length of the tets whose centroid lies within `[inner, outer)` of the centre.
double mean_edge_in_shell(const TetMesh& mesh, double inner, double outer) {
  double sum = 0.0;
  int count = 0;
  for (const auto& tet : mesh.tets) {
    Vec3 centroid = Vec3::Zero();
    for (const int n : tet)
      centroid += 0.25 * mesh.nodes[n];
    const double r = centroid.norm();
    if (r < inner || r >= outer) continue;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        sum += (mesh.nodes[tet[a]] - mesh.nodes[tet[b]]).norm();
    count += 6;
  }
  return count > 0 ? sum / count : 0.0;
}

TEST(TetMesherGrading, size_field_grades_from_the_surface_edge_to_the_cell_size_inside) {
  const SurfaceMesh sphere = make_icosphere(0.03, 4);  // edges ≈ 2.4 mm
  TetMeshingOptions options;
  options.cell_size = 0.010;
  options.grading_distance = 0.012;
  const TetMesh graded = mesh_closed_surface(sphere, options);
  const double near_surface = mean_edge_in_shell(graded, 0.026, 0.030);
  const double core_edges = mean_edge_in_shell(graded, 0.0, 0.012);
  EXPECT_LT(near_surface, 0.0045);
  EXPECT_GT(core_edges, 0.0075);
  EXPECT_LT(core_edges, 0.016);  // gmsh's 3D Delaunay edges run up to ~1.5× the target
  EXPECT_NEAR(total_volume(graded), enclosed_volume(sphere), 1e-9 * enclosed_volume(sphere));

  // Without the field gmsh extends the boundary's size inwards: many more tets.
  TetMeshingOptions uniform;
  uniform.cell_size = 0.010;
  EXPECT_GT(mesh_closed_surface(sphere, uniform).tets.size(), 2 * graded.tets.size());
}

TEST(TetMesherGrading, optimised_graded_mesh_is_valid_with_no_slivers_and_deterministic) {
  const SurfaceMesh sphere = make_icosphere(0.02, 3);
  TetMeshingOptions options;
  options.cell_size = 0.006;
  options.grading_distance = 0.008;
  options.optimize_threshold = 0.5;
  const TetMesh body = mesh_closed_surface(sphere, options);
  const TetQualityReport report = tet_quality(body);
  EXPECT_EQ(report.inverted, 0u);
  EXPECT_GT(report.min_dihedral_degrees, 5.0);
  EXPECT_EQ(mesh_closed_surface(sphere, options), body);  // deterministic
}

TEST(TetMesherGrading, refuses_options_out_of_range) {
  const SurfaceMesh sphere = make_icosphere(0.02, 1);
  TetMeshingOptions options;
  options.optimize_threshold = 2.0;
  EXPECT_THROW(mesh_closed_surface(sphere, options), UsageError);
}

}  // namespace
}  // namespace viscera::core
