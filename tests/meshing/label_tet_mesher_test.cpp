// Label map → tetrahedra with CGAL Mesh_3 (issue 3 §4a, §8): volumes against the surface and
// the analytic value, no inverted tets, labels kept, per-label sizes, determinism, and the
// visual surface embedded in the tets.

#include "importers/meshing/label_tet_mesher.h"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <thread>

#include "core/error.h"
#include "core/mesh/tet_quality.h"
#include "importers/meshing/label_body.h"
#include "tests/meshing/label_phantoms.h"

namespace viscera {
namespace {

using importers::LabelTetMeshingOptions;

std::map<int, double> volume_per_label(const core::TetMesh& body) {
  std::map<int, double> volumes;
  for (std::size_t t = 0; t < body.tets.size(); ++t)
    volumes[body.tet_labels[t]] += core::signed_volume(body, static_cast<int>(t));
  return volumes;
}

std::map<int, std::size_t> count_per_label(const core::TetMesh& body) {
  std::map<int, std::size_t> counts;
  for (const int l : body.tet_labels)
    ++counts[l];
  return counts;
}

TEST(LabelTetMesher, spheroid_tets_fill_the_surface_volume_within_one_percent) {
  const auto frame = testing::PhantomFrame::rotated(35.0);
  const double a = 0.018, c = 0.027;
  const auto labels = testing::spheroid_phantom(a, c, frame);
  importers::LabelBodyOptions options;
  options.visual_surface = importers::VisualSurfaceSource::LabelContour;
  options.tets.cell_size = 0.003;
  // A quarter voxel: the inscribed facets of a radius of 18 voxels then lose 0.6 % of the volume
  // (1.4 % at the default half voxel).
  options.tets.facet_distance = 0.00025;
  const auto made = importers::mesh_label_body(labels, options, "spheroid.vti");
  const double surface_volume = core::enclosed_volume(made.surface.mesh);
  EXPECT_NEAR(core::total_volume(made.body) / surface_volume, 1.0, 0.01);
  EXPECT_NEAR(core::total_volume(made.body) / testing::spheroid_volume(a, c), 1.0, 0.02);
  EXPECT_EQ(made.quality.inverted, 0u);
  EXPECT_EQ(made.quality.tets, made.body.tets.size());
  EXPECT_GT(made.body.tets.size(), 1000u);
  EXPECT_EQ(count_per_label(made.body).size(), 1u);
  EXPECT_EQ(made.body.tet_labels.front(), 1);
  EXPECT_NO_THROW(core::check_tet_mesh(made.body, "spheroid tets"));
  // Mesh_3's criteria hold: radius-edge ratio ≤ 3 before exudation only removes slivers.
  EXPECT_LE(made.quality.max_radius_edge_ratio, 3.0 * 1.05);
}

TEST(LabelTetMesher, torus_tets_fill_the_surface_volume_within_one_percent) {
  const auto frame = testing::PhantomFrame::rotated(-50.0);
  const double R = 0.022, r = 0.009;
  const auto labels = testing::torus_phantom(R, r, frame);
  importers::LabelBodyOptions options;
  options.visual_surface = importers::VisualSurfaceSource::LabelContour;
  options.tets.cell_size = 0.003;
  options.tets.facet_distance = 0.00025;
  const auto made = importers::mesh_label_body(labels, options, "torus.vti");
  EXPECT_NEAR(core::total_volume(made.body) / core::enclosed_volume(made.surface.mesh), 1.0, 0.01);
  EXPECT_NEAR(core::total_volume(made.body) / testing::torus_volume(R, r), 1.0, 0.02);
  EXPECT_EQ(made.quality.inverted, 0u);
}

TEST(LabelTetMesher, two_labels_keep_their_regions_and_sizes) {
  const auto frame = testing::PhantomFrame::rotated(15.0);
  const double a = 0.018, c = 0.024, inner = 0.009;
  const auto labels = testing::shell_phantom(a, c, inner, frame);
  LabelTetMeshingOptions options;
  options.cell_size = 0.003;
  options.label_cell_size[2] = 0.0015;
  const auto body = importers::mesh_label_map(labels, options, "shell.vti");
  const auto volumes = volume_per_label(body);
  ASSERT_EQ(volumes.size(), 2u);
  const double sphere = testing::spheroid_volume(inner, inner);
  EXPECT_NEAR(volumes.at(2) / sphere, 1.0, 0.03);
  EXPECT_NEAR(volumes.at(1) / (testing::spheroid_volume(a, c) - sphere), 1.0, 0.03);
  // The finer size of label 2 gives it smaller tets.
  const auto counts = count_per_label(body);
  EXPECT_LT(volumes.at(2) / static_cast<double>(counts.at(2)),
            0.5 * volumes.at(1) / static_cast<double>(counts.at(1)));
  // Every tet of label 2 lies inside the sphere (within a facet distance).
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    if (body.tet_labels[t] != 2) continue;
    core::Vec3 centroid = core::Vec3::Zero();
    for (const int n : body.tets[t])
      centroid += body.nodes[n] / 4.0;
    ASSERT_LT((centroid - frame.centre).norm(), inner + 0.001) << "tet " << t;
  }
  EXPECT_EQ(core::tet_quality(body).inverted, 0u);
}

TEST(LabelTetMesher, one_label_of_several_is_meshed_alone) {
  const auto labels = testing::shell_phantom(0.015, 0.02, 0.008, testing::PhantomFrame::rotated(0));
  LabelTetMeshingOptions options;
  options.label = 2;
  options.cell_size = 0.002;
  options.facet_distance = 0.00025;
  const auto body = importers::mesh_label_map(labels, options, "shell.vti");
  EXPECT_EQ(count_per_label(body).size(), 1u);
  EXPECT_NEAR(core::total_volume(body) / testing::spheroid_volume(0.008, 0.008), 1.0, 0.03);
}

TEST(LabelTetMesher, sequential_meshing_is_deterministic) {
  const auto labels = testing::spheroid_phantom(0.01, 0.013, testing::PhantomFrame::rotated(5));
  LabelTetMeshingOptions options;
  options.cell_size = 0.002;
  EXPECT_EQ(importers::mesh_label_map(labels, options, "a.vti"),
            importers::mesh_label_map(labels, options, "a.vti"));
}

TEST(LabelTetMesher, parallel_meshing_gives_valid_tets_of_the_same_volume) {
  const auto labels = testing::spheroid_phantom(0.018, 0.027, testing::PhantomFrame::rotated(35));
  LabelTetMeshingOptions options;
  options.cell_size = 0.0025;
  const auto sequential = importers::mesh_label_map(labels, options, "p.vti");
  options.threads = 2;
  const auto parallel = importers::mesh_label_map(labels, options, "p.vti");
  EXPECT_EQ(core::tet_quality(parallel).inverted, 0u);
  EXPECT_NEAR(core::total_volume(parallel) / core::total_volume(sequential), 1.0, 0.005);
  EXPECT_NO_THROW(core::check_tet_mesh(parallel, "parallel tets"));
}

TEST(LabelTetMesher, target_tet_count_sets_the_cell_size) {
  const auto labels = testing::spheroid_phantom(0.018, 0.027, testing::PhantomFrame::rotated(35));
  LabelTetMeshingOptions options;
  options.target_tets = 20000;
  importers::ResolvedTetCriteria used;
  const auto body =
      importers::mesh_label_map(labels, options, "t.vti", core::Progress::none(), &used);
  EXPECT_GT(used.cell_size, 0.0);
  // An estimate from the volume: within a factor of two (surface refinement adds tets on
  // small bodies).
  EXPECT_GT(body.tets.size(), 10000u);
  EXPECT_LT(body.tets.size(), 40000u);
}

TEST(LabelTetMesher, embedded_surface_vertices_rebuild_from_their_weights) {
  const auto labels = testing::torus_phantom(0.02, 0.008, testing::PhantomFrame::rotated(70));
  importers::LabelBodyOptions options;
  options.visual_surface = importers::VisualSurfaceSource::LabelContour;
  options.tets.cell_size = 0.003;
  options.surface.target_triangles = 4000;
  const auto made = importers::mesh_label_body(labels, options, "torus.vti");
  ASSERT_EQ(made.embedding.tet.size(), made.surface.mesh.vertices.size());
  EXPECT_LT(importers::embedding_error(made.surface.mesh, made.embedding, made.body), 1e-12);
  for (std::size_t v = 0; v < made.embedding.weights.size(); ++v) {
    const auto& w = made.embedding.weights[v];
    ASSERT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-9);
    // A visual vertex lies in its tet or just outside the body (within a facet distance).
    ASSERT_GT(*std::min_element(w.begin(), w.end()), -0.5) << "vertex " << v;
  }
  for (const char* stage : {"surface", "tets", "embedding", "quality"})
    EXPECT_GE(made.seconds.at(stage), 0.0) << stage;
}

TEST(LabelTetMesher, cancel_stops_mesh_3_refinement_early) {
  const auto labels = testing::spheroid_phantom(0.018, 0.027, testing::PhantomFrame::rotated(35));
  LabelTetMeshingOptions options;
  options.cell_size = 0.0004;  // millions of tets: minutes of refinement if it ran to the end
  core::Progress progress;
  const auto start = std::chrono::steady_clock::now();
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    progress.cancel();
  });
  EXPECT_THROW(importers::mesh_label_map(labels, options, "c.vti", progress), core::CancelledError);
  canceller.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10.0);
}

TEST(LabelTetMesher, empty_map_is_refused_naming_the_file) {
  core::LabelMap empty;
  empty.image.scalar_type = core::ScalarType::UInt16;
  empty.image.dims = {6, 5, 4};
  empty.image.allocate();
  try {
    importers::mesh_label_map(empty, {}, "/scans/empty_labels.vti");
    FAIL() << "an empty map was meshed";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/scans/empty_labels.vti"), std::string::npos);
  }
}

TEST(LabelTetMesher, criteria_out_of_range_are_usage_errors) {
  const auto labels = testing::spheroid_phantom(0.01, 0.01, testing::PhantomFrame::rotated(0));
  LabelTetMeshingOptions options;
  options.facet_angle_degrees = 40.0;
  EXPECT_THROW(importers::mesh_label_map(labels, options, "x.vti"), core::UsageError);
  options = {};
  options.cell_radius_edge_ratio = 1.0;
  EXPECT_THROW(importers::mesh_label_map(labels, options, "x.vti"), core::UsageError);
  options = {};
  options.label_cell_size[1] = -1.0;
  EXPECT_THROW(importers::mesh_label_map(labels, options, "x.vti"), core::UsageError);
}

}  // namespace
}  // namespace viscera
