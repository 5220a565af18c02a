// Label map → surface (issue 3 §3, §8): generated phantoms against their analytic area and
// volume, watertight, outward, free of self-intersections, in the map's world frame.

#include "importers/meshing/label_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "core/error.h"
#include "importers/meshing/closed_surface_repair.h"
#include "importers/meshing/label_crop.h"
#include "tests/meshing/label_phantoms.h"

namespace viscera {
namespace {

using importers::LabelSurfaceOptions;

core::Vec3 area_centroid(const core::SurfaceMesh& mesh) {
  core::Vec3 sum = core::Vec3::Zero();
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const auto &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double w = 0.5 * (b - a).cross(c - a).norm();
    sum += w * (a + b + c) / 3.0;
    area += w;
  }
  return sum / area;
}

/// Euler characteristic V − E + F of a closed triangle mesh (E = 3F/2).
long euler_characteristic(const core::SurfaceMesh& mesh) {
  const long f = static_cast<long>(mesh.triangles.size());
  return static_cast<long>(mesh.vertices.size()) - 3 * f / 2 + f;
}

TEST(LabelSurface, spheroid_area_and_volume_within_two_percent_of_analytic) {
  const auto frame = testing::PhantomFrame::rotated(35.0);
  const double a = 0.018, c = 0.027;
  const auto labels = testing::spheroid_phantom(a, c, frame);
  const auto surface = importers::label_surface(labels, 1, LabelSurfaceOptions{}, "spheroid.vti");
  EXPECT_NEAR(core::surface_area(surface.mesh) / testing::spheroid_area(a, c), 1.0, 0.02);
  EXPECT_NEAR(core::enclosed_volume(surface.mesh) / testing::spheroid_volume(a, c), 1.0, 0.02);
  EXPECT_LT((area_centroid(surface.mesh) - frame.centre).norm(), 0.2e-3);
  EXPECT_NO_THROW(importers::check_closed_surface(surface.mesh, "spheroid"));
  EXPECT_EQ(euler_characteristic(surface.mesh), 2);
  EXPECT_EQ(surface.mesh.normals.size(), surface.mesh.vertices.size());
}

TEST(LabelSurface, torus_area_and_volume_within_two_percent_and_genus_one) {
  const auto frame = testing::PhantomFrame::rotated(-50.0);
  const double R = 0.022, r = 0.009;
  const auto labels = testing::torus_phantom(R, r, frame);
  const auto surface = importers::label_surface(labels, 1, LabelSurfaceOptions{}, "torus.vti");
  EXPECT_NEAR(core::surface_area(surface.mesh) / testing::torus_area(R, r), 1.0, 0.02);
  EXPECT_NEAR(core::enclosed_volume(surface.mesh) / testing::torus_volume(R, r), 1.0, 0.02);
  EXPECT_NO_THROW(importers::check_closed_surface(surface.mesh, "torus"));
  EXPECT_EQ(euler_characteristic(surface.mesh), 0);
}

TEST(LabelSurface, decimation_meets_the_budget_and_keeps_the_shape) {
  const auto frame = testing::PhantomFrame::rotated(10.0);
  const double a = 0.018, c = 0.027;
  const auto labels = testing::spheroid_phantom(a, c, frame);
  LabelSurfaceOptions options;
  options.target_triangles = 2000;
  const auto surface = importers::label_surface(labels, 1, options, "spheroid.vti");
  EXPECT_GT(surface.extracted_triangles, 5 * options.target_triangles);
  EXPECT_LE(surface.mesh.triangles.size(), options.target_triangles * 101 / 100);
  EXPECT_GE(surface.mesh.triangles.size(), options.target_triangles * 9 / 10);
  EXPECT_NEAR(core::surface_area(surface.mesh) / testing::spheroid_area(a, c), 1.0, 0.02);
  EXPECT_NEAR(core::enclosed_volume(surface.mesh) / testing::spheroid_volume(a, c), 1.0, 0.02);
  EXPECT_NO_THROW(importers::check_closed_surface(surface.mesh, "decimated spheroid"));
}

TEST(LabelSurface, mirrored_direction_matrix_still_gives_an_outward_surface) {
  const auto frame = testing::PhantomFrame::rotated(20.0, true);
  const auto labels = testing::spheroid_phantom(0.012, 0.015, frame);
  const auto surface = importers::label_surface(labels, 1, LabelSurfaceOptions{}, "mirrored.vti");
  EXPECT_GT(core::enclosed_volume(surface.mesh), 0.0);
  EXPECT_FALSE(surface.repair.reoriented);
  EXPECT_NO_THROW(importers::check_closed_surface(surface.mesh, "mirrored"));
  EXPECT_LT((area_centroid(surface.mesh) - frame.centre).norm(), 0.2e-3);
}

TEST(LabelSurface, labels_are_meshed_one_at_a_time_or_together) {
  const auto frame = testing::PhantomFrame::rotated(0.0);
  const auto labels = testing::shell_phantom(0.015, 0.02, 0.008, frame);
  EXPECT_EQ(importers::labels_present(labels), (std::vector<int>{1, 2}));
  const auto inner = importers::label_surface(labels, 2, {}, "shell.vti");
  const auto outer = importers::label_surface(labels, 1, {}, "shell.vti");
  const auto all = importers::label_surface(labels, 0, {}, "shell.vti");
  const double v_inner = core::enclosed_volume(inner.mesh);
  EXPECT_NEAR(v_inner / testing::spheroid_volume(0.008, 0.008), 1.0, 0.03);
  // Label 1 is a shell: its surface has an outer and an inner (cavity) component.
  EXPECT_NEAR((core::enclosed_volume(outer.mesh) + v_inner) / core::enclosed_volume(all.mesh), 1.0,
              0.01);
  EXPECT_EQ(euler_characteristic(outer.mesh), 4);
  EXPECT_EQ(euler_characteristic(all.mesh), 2);
}

TEST(LabelSurface, surface_touching_the_map_border_is_closed) {
  auto labels = testing::spheroid_phantom(0.01, 0.012, testing::PhantomFrame::rotated(0.0), 1, 0);
  const auto surface = importers::label_surface(labels, 1, {}, "cut.vti");
  EXPECT_NO_THROW(importers::check_closed_surface(surface.mesh, "cut"));
}

TEST(LabelSurface, empty_map_or_missing_label_is_refused_naming_the_file) {
  core::LabelMap empty;
  empty.image.scalar_type = core::ScalarType::UInt16;
  empty.image.dims = {8, 8, 8};
  empty.image.allocate();
  try {
    importers::label_surface(empty, 0, {}, "/data/empty.vti");
    FAIL() << "an empty map was meshed";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/data/empty.vti"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
  const auto labels = testing::spheroid_phantom(0.01, 0.01, testing::PhantomFrame::rotated(0.0));
  try {
    importers::label_surface(labels, 7, {}, "one.vti");
    FAIL() << "a missing label was meshed";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("label 7"), std::string::npos) << e.what();
  }
  core::LabelMap no_voxels;
  no_voxels.image.scalar_type = core::ScalarType::UInt16;
  EXPECT_THROW(importers::label_surface(no_voxels, 0, {}, "none.vti"), core::InputError);
}

}  // namespace
}  // namespace viscera
