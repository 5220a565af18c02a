#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh/surface_embedding.h"
#include "core/primitives/icosphere.h"
#include "simulator/cutting/hybrid_cut.h"
#include "tests/cutting/cut_checks.h"

namespace viscera::sim::cutting {
namespace {

using core::Vec3;

TEST(VisualSurfaceCut, the_visual_surface_is_split_along_the_cut_and_gets_cut_faces) {
  const core::TetMesh& ball = testing::cutting_ball();
  const core::SurfaceMesh visual = core::make_icosphere(0.0199, 5);
  const core::SurfaceEmbedding embedding = core::embed_points(visual.vertices, ball);
  const Vec3 normal = Vec3(0.3, 1, 0.2).normalized();
  const CutSurface plane = planar_cut_surface(0.004 * normal, normal, Vec3::UnitX(), 0.05, 0.05, 4);
  const TopologyChange change = hybrid_cut(ball, ball.nodes, plane, visual, embedding);
  ASSERT_TRUE(change.changed);
  const core::SurfaceMesh& out = change.visual;
  ASSERT_EQ(change.visual_embedding.tet.size(), out.vertices.size());
  EXPECT_GT(out.triangles.size(), visual.triangles.size());
  EXPECT_EQ(change.visual_cut_triangles.size(), change.cut_surface_faces.size());
  ASSERT_EQ(out.normals.size(), out.vertices.size());
  ASSERT_EQ(out.uvs.size(), out.vertices.size());
  const auto& flag = out.vertex_attributes.at("cut_face");
  for (int f : change.visual_cut_triangles) {
    for (int v : out.triangles[f])
      EXPECT_EQ(flag[v], 1.0);
  }
  // Every vertex follows a tet of the new body, and its embedding gives back its material
  // point; the original vertices stay inside their tets as much as they were before.
  const auto& mx = out.vertex_attributes.at("material_x");
  const auto& my = out.vertex_attributes.at("material_y");
  const auto& mz = out.vertex_attributes.at("material_z");
  const auto rest =
      core::embedded_positions(change.visual_embedding, change.mesh.tets, change.mesh.nodes);
  for (std::size_t v = 0; v < out.vertices.size(); ++v) {
    const int t = change.visual_embedding.tet[v];
    ASSERT_TRUE(t >= 0 && t < static_cast<int>(change.mesh.tets.size()));
    EXPECT_LT((rest[v] - Vec3(mx[v], my[v], mz[v])).norm(), 1e-12) << "vertex " << v;
    if (v < visual.vertices.size()) {
      const auto& w = change.visual_embedding.weights[v];
      const auto& w0 = embedding.weights[v];
      EXPECT_GE(std::min({w[0], w[1], w[2], w[3]}),
                std::min({w0[0], w0[1], w0[2], w0[3], 0.0}) - 1e-6)
          << "vertex " << v;
    }
  }
  // No visual triangle of the body's skin spans the cut: its corners lie on one side.
  const auto current =
      core::embedded_positions(change.visual_embedding, change.mesh.tets, change.current);
  std::size_t spanning = 0;
  for (std::size_t f = 0; f < out.triangles.size(); ++f) {
    if (std::find(change.visual_cut_triangles.begin(), change.visual_cut_triangles.end(),
                  static_cast<int>(f)) != change.visual_cut_triangles.end()) {
      continue;
    }
    double lo = 1.0, hi = -1.0;
    for (int v : out.triangles[f]) {
      const double s = (current[v] - 0.004 * normal).dot(normal);
      lo = std::min(lo, s), hi = std::max(hi, s);
    }
    if (lo < -1e-9 && hi > 1e-9) ++spanning;
  }
  EXPECT_EQ(spanning, 0u);
}

TEST(VisualSurfaceCut, a_second_cut_keeps_the_first_cuts_faces_and_cut_vertices_are_rest_points) {
  const core::TetMesh& ball = testing::cutting_ball();
  const core::SurfaceMesh visual = core::make_icosphere(0.0199, 4);
  const core::SurfaceEmbedding embedding = core::embed_points(visual.vertices, ball);
  const Vec3 n1 = Vec3(0.3, 1, 0.2).normalized(), n2 = Vec3(1, -0.2, 0.1).normalized();
  const TopologyChange first = hybrid_cut(
      ball, ball.nodes, planar_cut_surface(0.004 * n1, n1, n1.unitOrthogonal(), 0.05, 0.05, 4),
      visual, embedding);
  ASSERT_TRUE(first.changed);
  // The second cut crosses the first: the body it cuts is the first cut's, deformed nowhere.
  const TopologyChange second =
      hybrid_cut(first.mesh, first.mesh.nodes,
                 planar_cut_surface(-0.003 * n2, n2, n2.unitOrthogonal(), 0.05, 0.05, 4),
                 first.visual, first.visual_embedding);
  ASSERT_TRUE(second.changed);
  const auto count_cut_faces = [](const core::SurfaceMesh& mesh) {
    const auto& flag = mesh.vertex_attributes.at("cut_face");
    std::size_t faces = 0;
    for (const auto& t : mesh.triangles)
      faces += flag[t[0]] == 1.0 && flag[t[1]] == 1.0 && flag[t[2]] == 1.0;
    return faces;
  };
  // Every face either cut made is still a cut face (the first cut's may have been split).
  EXPECT_EQ(count_cut_faces(first.visual), first.cut_surface_faces.size());
  EXPECT_GE(count_cut_faces(second.visual),
            first.cut_surface_faces.size() + second.cut_surface_faces.size());
  // Vertices are rest points, like the uncut surface's: a cut vertex is its material point.
  const auto& flag = second.visual.vertex_attributes.at("cut_face");
  const auto& mx = second.visual.vertex_attributes.at("material_x");
  const auto& my = second.visual.vertex_attributes.at("material_y");
  const auto& mz = second.visual.vertex_attributes.at("material_z");
  std::size_t cut_vertices = 0;
  for (std::size_t v = 0; v < second.visual.vertices.size(); ++v) {
    if (flag[v] != 1.0) continue;
    ++cut_vertices;
    EXPECT_LT((second.visual.vertices[v] - Vec3(mx[v], my[v], mz[v])).norm(), 1e-12);
  }
  EXPECT_GT(cut_vertices, 0u);
}

}  // namespace
}  // namespace viscera::sim::cutting
