#include "tests/cutting/cut_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/mesh/surface_mesh.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"
#include "simulator/cutting/cut_classification.h"
#include "simulator/cutting/fragments.h"

namespace viscera::testing {

using core::Vec3;

const core::TetMesh& cutting_ball(double radius, int subdivisions) {
  static std::map<std::pair<double, int>, core::TetMesh> cache;
  auto [it, inserted] = cache.try_emplace({radius, subdivisions});
  if (inserted) it->second = core::mesh_closed_surface(core::make_icosphere(radius, subdivisions));
  return it->second;
}

double smallest_dihedral(const std::vector<core::Tetrahedron>& tets, const std::vector<Vec3>& x) {
  double smallest = 180.0;
  for (const auto& t : tets) {
    smallest =
        std::min(smallest, sim::cutting::min_dihedral_degrees(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
  }
  return smallest;
}

namespace {

core::Triangle canonical(core::Triangle f) {
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

}  // namespace

void expect_valid_cut(const core::TetMesh& before, const std::vector<Vec3>& current_before,
                      const sim::cutting::TopologyChange& change, double min_dihedral) {
  const core::TetMesh& mesh = change.mesh;
  const std::size_t n = mesh.nodes.size();
  ASSERT_EQ(change.current.size(), n);
  ASSERT_EQ(change.node_source_offset.size(), n + 1);
  ASSERT_EQ(change.tet_parent.size(), mesh.tets.size());
  ASSERT_EQ(change.on_cut.size(), n);
  // Positive tets and no degenerate ones, in both configurations.
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& q = mesh.tets[t];
    for (int v : q)
      ASSERT_TRUE(v >= 0 && v < static_cast<int>(n)) << "tet " << t;
    ASSERT_GT(core::signed_volume(mesh, static_cast<int>(t)), 0.0) << "rest tet " << t;
    ASSERT_GT(core::signed_volume(change.current[q[0]], change.current[q[1]], change.current[q[2]],
                                  change.current[q[3]]),
              0.0)
        << "current tet " << t;
    ASSERT_LT(change.tet_parent[t], static_cast<int>(before.tets.size()));
  }
  const double bound = std::min({min_dihedral, smallest_dihedral(before.tets, before.nodes),
                                 smallest_dihedral(before.tets, current_before)});
  EXPECT_GE(smallest_dihedral(mesh.tets, mesh.nodes), bound);
  EXPECT_GE(smallest_dihedral(mesh.tets, change.current), bound);
  // Volume kept in both configurations.
  const double rest_before = core::total_volume(before);
  EXPECT_NEAR(core::total_volume(mesh), rest_before, 1e-9 * rest_before);
  core::TetMesh current_before_mesh = before, current_after_mesh = mesh;
  current_before_mesh.nodes = current_before;
  current_after_mesh.nodes = change.current;
  const double cur_before = core::total_volume(current_before_mesh);
  EXPECT_NEAR(core::total_volume(current_after_mesh), cur_before, 1e-9 * cur_before);
  // The surface is exactly the boundary of the tets, oriented outward.
  std::vector<core::Triangle> expected = core::boundary_faces(mesh.tets), actual;
  for (auto& f : expected)
    f = canonical(f);
  for (const auto& f : mesh.surface_faces)
    actual.push_back(canonical(f));
  std::sort(expected.begin(), expected.end());
  std::sort(actual.begin(), actual.end());
  EXPECT_EQ(actual, expected);
  // Every fragment is a closed, consistently oriented (edge-manifold) surface.
  for (const auto& fragment : sim::cutting::body_fragments(mesh)) {
    const core::TetMesh piece = sim::cutting::fragment_mesh(mesh, fragment);
    core::SurfaceMesh surface;
    surface.vertices = piece.nodes;
    surface.triangles = piece.surface_faces;
    EXPECT_TRUE(core::is_closed_and_consistently_oriented(surface))
        << "fragment of " << fragment.tets.size() << " tets";
    EXPECT_GT(fragment.rest_volume, 0.0);
  }
  // Node sources reproduce both configurations from the old nodes.
  const double scale =
      (core::bounds(core::SurfaceMesh{before.nodes, {}, {}, {}, {}}).size()).norm();
  for (std::size_t i = 0; i < n; ++i) {
    auto [begin, end] = change.sources(static_cast<int>(i));
    ASSERT_NE(begin, end) << "node " << i;
    double sum = 0.0;
    Vec3 rest = Vec3::Zero(), cur = Vec3::Zero();
    for (auto* s = begin; s != end; ++s) {
      ASSERT_GE(s->weight, -1e-12);
      ASSERT_LT(s->old_node, static_cast<int>(before.nodes.size()));
      sum += s->weight;
      rest += s->weight * before.nodes[s->old_node];
      cur += s->weight * current_before[s->old_node];
    }
    ASSERT_NEAR(sum, 1.0, 1e-9) << "node " << i;
    ASSERT_LT((rest - mesh.nodes[i]).norm(), 1e-9 * scale) << "rest of node " << i;
    ASSERT_LT((cur - change.current[i]).norm(), 1e-9 * scale) << "current of node " << i;
  }
  // The relaxation's node classes: nodes of the original surface never move.
  for (const auto& f : before.surface_faces) {
    for (int v : f) {
      ASSERT_EQ(mesh.nodes[v], before.nodes[v]) << "surface node " << v << " moved (rest)";
      ASSERT_EQ(change.current[v], current_before[v]) << "surface node " << v << " moved";
    }
  }
  for (int f : change.cut_surface_faces) {
    ASSERT_LT(f, static_cast<int>(mesh.surface_faces.size()));
    for (int v : mesh.surface_faces[f])
      EXPECT_TRUE(change.on_cut[v]);
  }
}

}  // namespace viscera::testing
