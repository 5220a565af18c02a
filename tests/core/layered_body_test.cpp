#include "core/modelling/layered_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "core/error.h"
#include "core/primitives/ball_primitive.h"
#include "core/primitives/flat_primitive.h"
#include "core/primitives/pipe_primitive.h"
#include "tests/core/primitive_checks.h"

namespace viscera::core {
namespace {

std::size_t edge_count(const SurfaceMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      edges.insert(
          std::minmax(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]));
  return edges.size();
}

TEST(LayeredBody, kismo_net_of_a_ball_has_the_knots_springs_and_volume_of_its_layers) {
  const SurfaceMesh surface = tessellate_ball(make_ball(Vec3::Zero(), 0.03, 0, 3));
  const LayerOptions options{2, 0.004, LayerMode::Offset};
  const MassSpringNet net = layered_mass_spring_net(surface, options);
  const std::size_t v = surface.vertices.size(), e = edge_count(surface),
                    f = surface.triangles.size();
  EXPECT_EQ(net.layer_count, 3);
  EXPECT_EQ(net.knots.size(), 3 * v);
  // Springs: the edges of every copy, one between each knot and its copy, one diagonal per quad.
  EXPECT_EQ(net.springs.size(), 3 * e + 2 * v + 2 * e);
  EXPECT_EQ(net.tets.size(), 2 * 3 * f);
  const TetMesh body = mass_spring_body(net);
  EXPECT_NO_THROW(check_tet_mesh(body, "net"));
  for (std::size_t t = 0; t < body.tets.size(); ++t)
    EXPECT_GT(signed_volume(body, static_cast<int>(t)), 0.0);
  EXPECT_EQ(body.surface_faces.size(), 2 * f);  // outer and inner copy, nothing else
  // The tets fill the wall: its volume is the outer minus the innermost copy's.
  const SurfaceMesh inner{
      std::vector<Vec3>(net.knots.end() - static_cast<std::ptrdiff_t>(v), net.knots.end()),
      surface.triangles,
      {},
      {},
      {}};
  EXPECT_NEAR(total_volume(body), enclosed_volume(surface) - enclosed_volume(inner), 1e-12);
  const double r = 0.03, t = 0.004;
  EXPECT_LT(std::abs(total_volume(body) / (4.0 / 3.0 * std::numbers::pi *
                                           (r * r * r - (r - t) * (r - t) * (r - t))) -
                     1.0),
            0.03);
  for (std::size_t s = 0; s < net.springs.size(); ++s)
    EXPECT_GT(net.rest_length[s], 0.0);
}

TEST(LayeredBody, scaled_copies_keep_the_shape_at_the_mean_thickness) {
  const SurfaceMesh surface = tessellate_ball(make_ball(Vec3(0.1, 0, 0), 0.02, 0, 2));
  const auto layers = layer_positions(surface, {2, 0.005, LayerMode::Scale});
  ASSERT_EQ(layers.size(), 3u);
  for (std::size_t i = 0; i < surface.vertices.size(); ++i) {
    EXPECT_NEAR((layers[2][i] - Vec3(0.1, 0, 0)).norm(), 0.015, 1e-9);
    EXPECT_NEAR((layers[1][i] - Vec3(0.1, 0, 0)).norm(), 0.0175, 1e-9);
  }
  EXPECT_THROW(layer_positions(surface, {1, 0.03, LayerMode::Scale}), UsageError);
}

TEST(LayeredBody, gmsh_shell_fills_exactly_the_wall_between_surface_and_copy) {
  const SurfaceMesh surface = tessellate_ball(make_ball(Vec3::Zero(), 0.03, 0, 3));
  const LayerOptions options{2, 0.005, LayerMode::Offset};
  const TetMesh shell = layered_shell_tets(surface, options);
  EXPECT_NO_THROW(check_tet_mesh(shell, "shell"));
  const auto layers = layer_positions(surface, options);
  const SurfaceMesh inner{layers.back(), surface.triangles, {}, {}, {}};
  EXPECT_NEAR(total_volume(shell) / (enclosed_volume(surface) - enclosed_volume(inner)), 1.0, 1e-9);
  EXPECT_EQ(shell.surface_faces.size(), 2 * surface.triangles.size());
  EXPECT_EQ(boundary_faces(shell.tets).size(),
            2 * surface.triangles.size());  // gmsh kept both walls as given
  for (std::size_t i = 0; i < surface.vertices.size(); ++i)
    EXPECT_EQ(shell.nodes[i], surface.vertices[i]);
  const SurfaceEmbedding embedding = embed_leading_nodes(shell, surface.vertices.size());
  const auto riding = embedded_positions(embedding, shell.tets, shell.nodes);
  for (std::size_t i = 0; i < surface.vertices.size(); ++i)
    EXPECT_LT((riding[i] - surface.vertices[i]).norm(), 1e-15);
}

TEST(LayeredBody, open_sheet_becomes_a_slab_both_ways) {
  FlatPrimitive flat = make_flat(Vec3::Zero(), Vec3(0.06, 0, 0), Vec3(0, 0.04, 0), 3, 4);
  flat.open = true;
  flat.steps_per_patch = 3;
  const SurfaceMesh sheet = tessellate_flat(flat);
  const LayerOptions options{2, 0.003, LayerMode::Offset};
  const MassSpringNet net = layered_mass_spring_net(sheet, options);
  EXPECT_NEAR(total_volume(mass_spring_body(net)), 0.06 * 0.04 * 0.003, 1e-12);
  const TetMesh slab = layered_shell_tets(sheet, options);
  EXPECT_NO_THROW(check_tet_mesh(slab, "slab"));
  EXPECT_NEAR(total_volume(slab), 0.06 * 0.04 * 0.003, 1e-12);
  const SurfaceMesh boundary{slab.nodes, boundary_faces(slab.tets), {}, {}, {}};
  EXPECT_TRUE(testing::is_watertight_and_outward(boundary));
}

TEST(LayeredBody, refuses_layers_thicker_than_a_thin_tube_allows) {
  PipePrimitive pipe;
  pipe.points = {{0, 0, 0}, {0.05, 0, 0}};
  pipe.radii = {0.002, 0.002};
  pipe.ring_segments = 12;
  const SurfaceMesh tube = tessellate_pipe(pipe);
  EXPECT_NO_THROW(layered_mass_spring_net(tube, {1, 0.0005, LayerMode::Offset}));
  EXPECT_THROW(layered_mass_spring_net(tube, {1, 0.005, LayerMode::Offset}), UsageError);
  EXPECT_THROW(layered_mass_spring_net(tube, {0, 0.001, LayerMode::Offset}), UsageError);
  EXPECT_THROW(layer_mode_from_string("shrink"), UsageError);
}

}  // namespace
}  // namespace viscera::core
