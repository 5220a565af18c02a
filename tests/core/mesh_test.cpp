#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/box.h"
#include "core/primitives/icosphere.h"

namespace viscera::core {
namespace {

TetMesh unit_cube_as_five_tets() {
  TetMesh mesh;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        mesh.nodes.emplace_back(i, j, k);
  // Corner indices: i + 2j + 4k. One central tet and four corner tets.
  mesh.tets = {{0, 1, 2, 4}, {1, 3, 2, 7}, {1, 4, 7, 5}, {2, 7, 4, 6}, {1, 2, 4, 7}};
  orient_tets_positively(mesh);
  mesh.surface_faces = boundary_faces(mesh.tets);
  return mesh;
}

TEST(TetMesh, five_tet_cube_has_unit_volume_and_closed_outward_boundary) {
  const TetMesh cube = unit_cube_as_five_tets();
  EXPECT_NEAR(total_volume(cube), 1.0, 1e-12);
  for (std::size_t t = 0; t < cube.tets.size(); ++t)
    EXPECT_GT(signed_volume(cube, static_cast<int>(t)), 0.0);
  EXPECT_EQ(cube.surface_faces.size(), 12u);
  SurfaceMesh boundary{cube.nodes, cube.surface_faces, {}, {}, {}};
  EXPECT_TRUE(is_closed_and_consistently_oriented(boundary));
  EXPECT_NEAR(enclosed_volume(boundary), 1.0, 1e-12);
  EXPECT_NEAR(surface_area(boundary), 6.0, 1e-12);
}

TEST(TetMesh, lumped_masses_add_up_to_density_times_volume) {
  const TetMesh cube = unit_cube_as_five_tets();
  const auto mass = lumped_node_masses(cube, 1000.0);
  EXPECT_NEAR(std::accumulate(mass.begin(), mass.end(), 0.0), 1000.0, 1e-9);
}

TEST(TetMesh, check_names_the_inverted_tet) {
  TetMesh cube = unit_cube_as_five_tets();
  std::swap(cube.tets[3][0], cube.tets[3][1]);
  try {
    check_tet_mesh(cube, "body.vtu");
    FAIL() << "inverted tet accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("body.vtu"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("tet 3"), std::string::npos);
  }
}

TEST(Icosphere, is_closed_outward_and_converges_to_the_sphere) {
  const double r = 0.04;
  double previous_error = 1.0;
  for (int s = 1; s <= 4; ++s) {
    const SurfaceMesh sphere = make_icosphere(r, s);
    EXPECT_EQ(sphere.triangles.size(), 20u * (1u << (2 * s)));
    EXPECT_TRUE(is_closed_and_consistently_oriented(sphere));
    const double exact = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const double error = std::abs(enclosed_volume(sphere) - exact) / exact;
    EXPECT_LT(error, previous_error);
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.01);
  const SurfaceMesh fine = make_icosphere(r, 4);
  EXPECT_NEAR(surface_area(fine), 4.0 * std::numbers::pi * r * r,
              0.01 * 4.0 * std::numbers::pi * r * r);
}

TEST(Icosphere, refuses_bad_arguments) {
  EXPECT_THROW(make_icosphere(-1.0, 2), UsageError);
  EXPECT_THROW(make_icosphere(1.0, 9), UsageError);
}

TEST(TetMesher, fills_a_sphere_with_positive_tets_matching_its_enclosed_volume) {
  const SurfaceMesh sphere = make_icosphere(0.03, 3);
  TetMeshingOptions options;
  options.cell_size = 0.008;
  const TetMesh body = mesh_closed_surface(sphere, options);
  ASSERT_FALSE(body.tets.empty());
  for (std::size_t t = 0; t < body.tets.size(); ++t)
    ASSERT_GT(signed_volume(body, static_cast<int>(t)), 0.0);
  EXPECT_NEAR(total_volume(body), enclosed_volume(sphere), 1e-6 * enclosed_volume(sphere));
  EXPECT_EQ(body.surface_faces, sphere.triangles);
  // The surface vertices come first and unchanged.
  for (std::size_t v = 0; v < sphere.vertices.size(); ++v)
    EXPECT_EQ(body.nodes[v], sphere.vertices[v]);
}

TEST(TetMesher, is_deterministic) {
  const SurfaceMesh sphere = make_icosphere(0.03, 2);
  EXPECT_EQ(mesh_closed_surface(sphere), mesh_closed_surface(sphere));
}

TEST(TetMesher, refuses_an_open_surface_with_a_clear_message) {
  SurfaceMesh sphere = make_icosphere(0.03, 2);
  sphere.triangles.pop_back();
  try {
    mesh_closed_surface(sphere);
    FAIL() << "open surface accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos);
  }
}

TEST(SurfaceEmbedding, reproduces_points_inside_and_near_the_body) {
  const SurfaceMesh coarse = make_icosphere(0.03, 2);
  const TetMesh body = mesh_closed_surface(coarse);
  const SurfaceMesh fine = make_icosphere(0.03, 3);  // slightly outside the inscribed body
  const SurfaceEmbedding embedding = embed_points(fine.vertices, body);
  ASSERT_EQ(embedding.tet.size(), fine.vertices.size());
  const auto positions = embedded_positions(embedding, body.tets, body.nodes);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    EXPECT_NEAR((positions[v] - fine.vertices[v]).norm(), 0.0, 1e-12);
    const auto& w = embedding.weights[v];
    EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-12);
    EXPECT_GT(*std::min_element(w.begin(), w.end()), -0.5) << "vertex embedded in a far tet";
  }
  // Moving the body rigidly moves the embedded points with it.
  std::vector<Vec3> moved = body.nodes;
  for (auto& n : moved)
    n += Vec3(0.01, -0.02, 0.005);
  const auto shifted = embedded_positions(embedding, body.tets, moved);
  EXPECT_NEAR((shifted[5] - fine.vertices[5] - Vec3(0.01, -0.02, 0.005)).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace viscera::core

namespace viscera::core {
namespace {

TEST(Box, is_closed_outward_with_the_exact_volume_and_area) {
  const SurfaceMesh box = make_box(Vec3(-0.1, 0.0, 0.2), Vec3(0.1, 0.05, 0.23), 0.01);
  EXPECT_TRUE(is_closed_and_consistently_oriented(box));
  EXPECT_NEAR(enclosed_volume(box), 0.2 * 0.05 * 0.03, 1e-12);
  EXPECT_NEAR(surface_area(box), 2 * (0.2 * 0.05 + 0.2 * 0.03 + 0.05 * 0.03), 1e-12);
  EXPECT_THROW(make_box(Vec3::Zero(), Vec3(1, 0, 1), 0.1), UsageError);
}

}  // namespace
}  // namespace viscera::core
