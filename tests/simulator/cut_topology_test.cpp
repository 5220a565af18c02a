// A cut through a body's holds (simulator/session/cut_topology.h, BodyTopology::released): a
// piece held only at nodes the cut passed through is cut loose, and the world drops those
// nodes' attachments; a piece that keeps another hold keeps them all.

#include "simulator/session/cut_topology.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "simulator/session/severed_pieces.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"

namespace viscera::sim {
namespace {

TEST(CutTopology, a_piece_held_only_where_the_cut_passed_is_released_and_no_other) {
  // Two pieces after a cut: a stump tet held at node 0 (off the cut) and node 1 (on it), and a
  // chip tet held only at node 4, on the cut.
  cutting::TopologyChange change;
  for (int i = 0; i < 8; ++i)
    change.mesh.nodes.push_back(
        core::Vec3(0.01 * (i % 4 == 1), 0.01 * (i % 4 == 2), 0.01 * (i % 4 == 3) + 0.1 * (i / 4)));
  change.mesh.tets = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  change.tet_parent = {0, 1};
  change.node_source_offset.push_back(0);
  for (int i = 0; i < 8; ++i) {
    change.node_source.push_back({i, 1.0});
    change.node_source_offset.push_back(i + 1);
  }
  change.on_cut = {0, 1, 0, 0, 1, 0, 0, 0};
  const std::vector<std::uint8_t> held = {1, 1, 0, 0, 1, 0, 0, 0};
  const BodyTopology topology = topology_of_cut(change, held);
  EXPECT_EQ(topology.released, (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 0, 0, 0}));
  // Without holds, nothing is released.
  EXPECT_EQ(topology_of_cut(change).released, std::vector<std::uint8_t>(8, 0));
}

TEST(CutTopology, released_nodes_lose_their_attachments_and_their_piece_comes_off) {
  World world(templates::build_from_template("hysteroscopy-polypectomy", {}, 1));
  const int polyp = world.body_index("polyp-1");
  const auto held = world.held_nodes(polyp);
  ASSERT_GT(std::count(held.begin(), held.end(), std::uint8_t{1}), 0);
  // The same topology, every base node released.
  const auto& model = *world.models()[static_cast<std::size_t>(polyp)];
  BodyTopology topology =
      unchanged_topology(model.mesh, world.state().range(world.state().positions, polyp));
  topology.released = held;
  world.topology_changed(polyp, topology);
  const auto after = world.held_nodes(polyp);
  EXPECT_EQ(std::count(after.begin(), after.end(), std::uint8_t{1}), 0);
  // Held nowhere, the polyp keeps its largest piece: the whole of it, nothing severed; the wall
  // is untouched.
  EXPECT_TRUE(
      severed_fragments(world.models()[static_cast<std::size_t>(polyp)]->mesh, after).empty());
  const int uterus = world.body_index("uterus");
  const auto wall = world.held_nodes(uterus);
  EXPECT_GT(std::count(wall.begin(), wall.end(), std::uint8_t{1}), 0);
  // Flags of the wrong length are refused.
  topology.released.pop_back();
  EXPECT_THROW(world.topology_changed(polyp, topology), core::InputError);
}

}  // namespace
}  // namespace viscera::sim
