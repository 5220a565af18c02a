#include "simulator/collision/penetration_depth.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"
#include "simulator/collision/spatial_hash.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// Colliding points of `a` in `b`, found by the spatial hash.
std::vector<int> colliding_points(const core::TetMesh& a, const core::TetMesh& b) {
  const std::vector<CollisionBodyView> bodies = {{a.nodes, a.tets}, {b.nodes, b.tets}};
  SpatialHash hash(mean_edge_length(bodies), 1009);
  std::vector<int> points;
  for (const auto& c : hash.detect(bodies, false)) {
    if (c.vertex_body == 0 && (points.empty() || points.back() != c.vertex))
      points.push_back(c.vertex);
  }
  return points;
}

VertexAdjacency adjacency_of(const core::TetMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  for (const auto& t : mesh.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.push_back({std::min(t[i], t[j]), std::max(t[i], t[j])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return VertexAdjacency::from_edges(mesh.nodes.size(), edges);
}

TEST(VertexAdjacency, from_tets_lists_each_edge_once_as_from_sorted_edges_does) {
  // A gmsh ball: edges shared by up to a dozen tets, nodes of valence 4 to 20.
  const core::TetMesh ball = core::mesh_closed_surface(core::make_icosphere(0.02, 2));
  const VertexAdjacency expected = adjacency_of(ball);
  const VertexAdjacency adjacency = VertexAdjacency::from_tets(ball.nodes.size(), ball.tets);
  EXPECT_EQ(adjacency.offsets, expected.offsets);
  EXPECT_EQ(adjacency.neighbours, expected.neighbours);
  // Every tet's six edges are there, both ways, and no node neighbours itself.
  for (const auto& t : ball.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const auto row = adjacency.of(t[i]);
        if (i != j) {
          EXPECT_TRUE(std::binary_search(row.begin(), row.end(), t[j]));
        }
      }
  for (int v = 0; v < static_cast<int>(ball.nodes.size()); ++v) {
    const auto row = adjacency.of(v);
    EXPECT_FALSE(std::binary_search(row.begin(), row.end(), v));
  }
}

TEST(PenetrationDepth, plane_gives_exact_depth_and_normal_and_propagates_inward) {
  // Slab b fills z ∈ [−0.05, 0]; block a's two lowest node layers sit 3 mm and 13 mm deep.
  core::TetMesh b = viscera::testing::tet_block(8, 8, 5, 0.01);
  for (auto& n : b.nodes)
    n += core::Vec3(-0.04, -0.04, -0.05);
  core::TetMesh a = viscera::testing::tet_block(2, 2, 3, 0.01);
  const double depth = 0.003;
  for (auto& n : a.nodes)
    n += core::Vec3(-0.0101, -0.0099, -0.01 - depth);
  const auto colliding = colliding_points(a, b);
  ASSERT_EQ(colliding.size(), 18u);  // two layers of 3 × 3 nodes
  const PenetratedSurface surface{b.nodes, b.surface_faces};
  const auto result = penetration_depths(a.nodes, adjacency_of(a), colliding, surface);
  ASSERT_EQ(result.size(), colliding.size());
  for (const auto& p : result) {
    const double z = a.nodes[p.point].z();
    EXPECT_NEAR(p.direction.z(), 1.0, 1e-12);
    if (std::abs(z + depth) < 1e-9) {
      EXPECT_TRUE(p.border);
      EXPECT_NEAR(p.depth, depth, 1e-12);
    } else {
      EXPECT_FALSE(p.border);
      EXPECT_NEAR(p.depth, depth + 0.01, 1e-12);  // propagated from the layer above
    }
  }
}

TEST(PenetrationDepth, sphere_depth_matches_the_distance_to_its_surface) {
  // A small block pressed into the top of a sphere of radius 5 cm.
  const double radius = 0.05;
  const core::TetMesh b = core::mesh_closed_surface(core::make_icosphere(radius, 4));
  core::TetMesh a = viscera::testing::tet_block(3, 3, 3, 0.004);
  for (auto& n : a.nodes)
    n += core::Vec3(-0.006, -0.006, radius - 0.006);
  const auto colliding = colliding_points(a, b);
  ASSERT_FALSE(colliding.empty());
  const auto result =
      penetration_depths(a.nodes, adjacency_of(a), colliding, {b.nodes, b.surface_faces});
  ASSERT_EQ(result.size(), colliding.size());
  for (const auto& p : result) {
    const core::Vec3& x = a.nodes[p.point];
    // The faceted sphere lies within 0.2 mm of the true one at this resolution.
    EXPECT_NEAR(p.depth, radius - x.norm(), 6e-4) << p.point;
    EXPECT_GT(p.direction.dot(x.normalized()), 0.95) << p.point;
  }
}

TEST(PenetrationDepth, segment_triangle_intersection_finds_the_crossing_parameter) {
  const core::Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_NEAR(segment_triangle_intersection({0.2, 0.2, -1}, {0.2, 0.2, 3}, a, b, c), 0.25, 1e-15);
  EXPECT_LT(segment_triangle_intersection({0.8, 0.8, -1}, {0.8, 0.8, 1}, a, b, c), 0.0);  // outside
  EXPECT_LT(segment_triangle_intersection({0.2, 0.2, 1}, {0.2, 0.2, 2}, a, b, c), 0.0);   // short
}

}  // namespace
}  // namespace viscera::sim
