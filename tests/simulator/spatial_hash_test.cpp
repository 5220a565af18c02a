#include "simulator/collision/spatial_hash.h"

#include <gtest/gtest.h>

#include <tuple>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// Every vertex–tet containment by testing all pairs.
std::vector<VertexInTet> brute_force(std::span<const CollisionBodyView> bodies,
                                     bool self_collisions) {
  std::vector<VertexInTet> found;
  for (std::size_t vb = 0; vb < bodies.size(); ++vb)
    for (std::size_t v = 0; v < bodies[vb].positions.size(); ++v)
      for (std::size_t tb = 0; tb < bodies.size(); ++tb) {
        if (tb == vb && !self_collisions) continue;
        for (std::size_t t = 0; t < bodies[tb].tets.size(); ++t) {
          const auto& tet = bodies[tb].tets[t];
          if (tb == vb && (tet[0] == static_cast<int>(v) || tet[1] == static_cast<int>(v) ||
                           tet[2] == static_cast<int>(v) || tet[3] == static_cast<int>(v))) {
            continue;
          }
          const auto& x = bodies[tb].positions;
          const auto w = core::barycentric(bodies[vb].positions[v], x[tet[0]], x[tet[1]], x[tet[2]],
                                           x[tet[3]]);
          if (w[0] >= 0 && w[1] >= 0 && w[2] >= 0 && w[3] >= 0) {
            found.push_back({static_cast<int>(vb), static_cast<int>(v), static_cast<int>(tb),
                             static_cast<int>(t), w});
          }
        }
      }
  return found;
}

TEST(SpatialHash, finds_exactly_the_pairs_of_a_brute_force_search_on_random_meshes) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    core::TetMesh a = viscera::testing::tet_block(4, 4, 3, 0.01);
    core::TetMesh b = viscera::testing::tet_block(3, 4, 4, 0.01);
    for (auto& n : b.nodes)
      n += core::Vec3(0.021, 0.004, 0.013);  // overlapping corner region
    viscera::testing::jiggle(a.nodes, 0.004, seed);
    viscera::testing::jiggle(b.nodes, 0.004, seed + 100);  // large enough to fold tets: self hits
    const std::vector<CollisionBodyView> bodies = {{a.nodes, a.tets}, {b.nodes, b.tets}};
    SpatialHash hash(mean_edge_length(bodies), 211);  // a small table: many hash collisions
    for (const bool self : {false, true}) {
      const auto expected = brute_force(bodies, self);
      const auto found = hash.detect(bodies, self);
      ASSERT_EQ(found.size(), expected.size()) << "seed " << seed << " self " << self;
      for (std::size_t i = 0; i < found.size(); ++i) {
        EXPECT_EQ(std::tie(found[i].vertex_body, found[i].vertex, found[i].tet_body, found[i].tet),
                  std::tie(expected[i].vertex_body, expected[i].vertex, expected[i].tet_body,
                           expected[i].tet));
        for (int k = 0; k < 4; ++k)
          EXPECT_NEAR(found[i].barycentric[k], expected[i].barycentric[k], 1e-12);
      }
      if (self) {
        EXPECT_GT(expected.size(), 0u);
      }
    }
  }
}

TEST(SpatialHash, uses_the_primes_of_teschner_2003) {
  const SpatialHash hash(1.0, 1000003);
  EXPECT_EQ(hash.hash(1, 0, 0), 73856093u % 1000003u);
  EXPECT_EQ(hash.hash(0, 1, 0), 19349663u % 1000003u);
  EXPECT_EQ(hash.hash(0, 0, 1), 83492791u % 1000003u);
  EXPECT_EQ(hash.hash(1, 1, 1), (73856093u ^ 19349663u ^ 83492791u) % 1000003u);
  EXPECT_THROW(SpatialHash(0.0, 10), core::UsageError);
}

TEST(SpatialHash, separated_bodies_do_not_collide) {
  core::TetMesh a = viscera::testing::tet_block(3, 3, 3, 0.01);
  core::TetMesh b = viscera::testing::tet_block(3, 3, 3, 0.01);
  for (auto& n : b.nodes)
    n.z() += 0.0301;
  const std::vector<CollisionBodyView> bodies = {{a.nodes, a.tets}, {b.nodes, b.tets}};
  SpatialHash hash(0.01, 101);
  EXPECT_TRUE(hash.detect(bodies, false).empty());
  EXPECT_TRUE(hash.detect(bodies, true).empty());  // an undeformed block does not self-collide
}

}  // namespace
}  // namespace viscera::sim
