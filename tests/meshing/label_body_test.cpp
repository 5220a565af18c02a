// The label map → body pipeline's own choices (issue 20 §1–2): the visual surface taken from the
// tets' boundary, and the time budget that turns a stage running too long into a clear refusal.

#include "importers/meshing/label_body.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "core/error.h"
#include "core/mesh/tet_quality.h"
#include "importers/meshing/closed_surface_repair.h"
#include "tests/meshing/label_phantoms.h"

namespace viscera {
namespace {

using importers::LabelBodyOptions;
using importers::VisualSurfaceSource;

TEST(LabelBody, tet_boundary_surface_is_closed_outward_embedded_exactly_and_on_the_spheroid) {
  const auto frame = testing::PhantomFrame::rotated(35.0);
  const double a = 0.018, c = 0.027;
  const auto labels = testing::spheroid_phantom(a, c, frame);
  LabelBodyOptions options;
  options.visual_surface = VisualSurfaceSource::TetBoundary;
  options.tets.cell_size = 0.003;
  const auto made = importers::mesh_label_body(labels, options, "spheroid.vti");
  const auto& surface = made.surface.mesh;
  ASSERT_GT(surface.triangles.size(), 500u);
  EXPECT_EQ(surface.triangles.size(), made.body.surface_faces.size());
  EXPECT_NO_THROW(importers::check_closed_surface(surface, "tet boundary"));
  // It bounds exactly the tets' volume, and each vertex is a node of its tet.
  EXPECT_NEAR(core::enclosed_volume(surface) / core::total_volume(made.body), 1.0, 1e-9);
  EXPECT_EQ(importers::embedding_error(surface, made.embedding, made.body), 0.0);
  // Mesh_3 put every boundary node on the labels' boundary: within a voxel of the spheroid.
  const double voxel = frame.spacing.maxCoeff();
  for (const auto& p : surface.vertices) {
    const core::Vec3 q = frame.direction.transpose() * (p - frame.centre);
    const double level =
        std::sqrt((q.x() * q.x() + q.y() * q.y()) / (a * a) + q.z() * q.z() / (c * c));
    ASSERT_NEAR(level, 1.0, voxel / a) << p.transpose();
  }
  EXPECT_NEAR(core::total_volume(made.body) / testing::spheroid_volume(a, c), 1.0, 0.02);
  EXPECT_EQ(made.quality.inverted, 0u);
}

TEST(LabelBody, time_budget_stops_the_pipeline_with_the_stage_and_the_budget) {
  const auto labels = testing::spheroid_phantom(0.018, 0.027, testing::PhantomFrame::rotated(35));
  for (const auto source : {VisualSurfaceSource::TetBoundary, VisualSurfaceSource::LabelContour}) {
    LabelBodyOptions options;
    options.visual_surface = source;
    options.tets.cell_size = 0.0004;  // millions of tets: minutes if it ran to the end
    options.time_limit_seconds = 0.5;
    const auto start = std::chrono::steady_clock::now();
    try {
      importers::mesh_label_body(labels, options, "big.vti");
      FAIL() << "the pipeline outlived its time budget";
    } catch (const core::ValidationError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("big.vti"), std::string::npos) << message;
      EXPECT_NE(message.find("time budget of 0.5 s"), std::string::npos) << message;
      EXPECT_NE(message.find("tetrahedra"), std::string::npos) << message;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 30.0) << "cancellation took too long";
  }
}

}  // namespace
}  // namespace viscera
