// The watertight / outward / self-intersection checks of surfaces made from label maps (issue 3
// §3, §7): local defects are repaired, the rest refused with the file and the reason.

#include "importers/meshing/closed_surface_repair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/primitives/box.h"

namespace viscera {
namespace {

core::SurfaceMesh unit_box() {
  return core::make_box(core::Vec3::Zero(), core::Vec3::Ones(), 0.25);
}

void turn_inside_out(core::SurfaceMesh& mesh) {
  for (auto& t : mesh.triangles)
    std::swap(t[1], t[2]);
}

TEST(ClosedSurfaceRepair, a_good_box_passes_unchanged_in_shape) {
  auto box = unit_box();
  ASSERT_NO_THROW(importers::check_closed_surface(box, "box"));
  const auto report = importers::repair_closed_surface(box, "box");
  EXPECT_FALSE(report.any());
  EXPECT_NEAR(core::enclosed_volume(box), 1.0, 1e-12);
}

TEST(ClosedSurfaceRepair, inside_out_surface_is_refused_by_the_check_and_turned_by_repair) {
  auto box = unit_box();
  turn_inside_out(box);
  try {
    importers::check_closed_surface(box, "inside_out.stl");
    FAIL() << "an inward surface passed";
  } catch (const core::ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("inside_out.stl"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("outward"), std::string::npos) << e.what();
  }
  const auto report = importers::repair_closed_surface(box, "inside_out.stl");
  EXPECT_TRUE(report.reoriented);
  EXPECT_NEAR(core::enclosed_volume(box), 1.0, 1e-12);
  EXPECT_NO_THROW(importers::check_closed_surface(box, "repaired"));
}

TEST(ClosedSurfaceRepair, a_missing_triangle_is_refused_by_the_check_and_filled_by_repair) {
  auto box = unit_box();
  box.triangles.pop_back();
  EXPECT_THROW(importers::check_closed_surface(box, "holed.stl"), core::ValidationError);
  const auto report = importers::repair_closed_surface(box, "holed.stl");
  EXPECT_EQ(report.filled_holes, 1u);
  EXPECT_NEAR(core::enclosed_volume(box), 1.0, 1e-12);
  EXPECT_NO_THROW(importers::check_closed_surface(box, "filled"));
}

TEST(ClosedSurfaceRepair, duplicated_points_are_joined) {
  auto box = unit_box();
  // Give triangle 0 its own copies of its corners: three open seams around it.
  for (int c = 0; c < 3; ++c) {
    box.vertices.push_back(box.vertices[box.triangles[0][c]]);
    box.triangles[0][c] = static_cast<int>(box.vertices.size()) - 1;
  }
  EXPECT_THROW(importers::check_closed_surface(box, "seams"), core::ValidationError);
  const auto report = importers::repair_closed_surface(box, "seams");
  EXPECT_EQ(report.merged_vertices, 3u);
  EXPECT_NO_THROW(importers::check_closed_surface(box, "joined"));
}

TEST(ClosedSurfaceRepair, interpenetrating_components_are_refused_with_the_reason) {
  auto box = unit_box();
  auto other = core::make_box(core::Vec3::Constant(0.5), core::Vec3::Constant(1.5), 0.25);
  const int offset = static_cast<int>(box.vertices.size());
  box.vertices.insert(box.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles)
    box.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  try {
    importers::check_closed_surface(box, "crossing.stl");
    FAIL() << "a self-intersecting surface passed";
  } catch (const core::ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("crossing.stl"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("intersects itself"), std::string::npos) << e.what();
  }
  try {
    importers::repair_closed_surface(box, "crossing.stl");
    FAIL() << "two crossing boxes were accepted";
  } catch (const core::ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("crossing.stl"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("intersects itself"), std::string::npos) << e.what();
  }
}

TEST(ClosedSurfaceRepair, non_finite_coordinates_are_refused_naming_the_vertex) {
  auto box = unit_box();
  box.vertices[5].y() = std::numeric_limits<double>::quiet_NaN();
  for (const bool repair : {false, true}) {
    try {
      if (repair) {
        importers::repair_closed_surface(box, "nan.obj");
      } else {
        importers::check_closed_surface(box, "nan.obj");
      }
      FAIL() << "a NaN coordinate passed";
    } catch (const core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("nan.obj"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("vertex 5"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace viscera
