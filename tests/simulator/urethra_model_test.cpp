#include "simulator/physics/urethra_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::sim {
namespace {

/// The endoscope on the centre line at z, pointing along it, moving with `speed` m/s.
EndoscopeState on_centre_line(const UrethraModel& model, double z, double speed = 0.0,
                              double spin = 0.0) {
  EndoscopeState e;
  e.tip = model.centre_line(z);
  e.pitch = std::atan(2.0 * model.parameters().curvature * z);
  const core::Vec3 axis(0.0, std::sin(e.pitch), std::cos(e.pitch));
  e.velocity = speed * axis;
  e.spin_rate = spin;
  return e;
}

TEST(UrethraModel, lattice_sits_on_the_parabola_and_widens_to_the_endoscope_behind_the_tip) {
  const UrethraModel model;
  const auto& p = model.parameters();
  const auto sections = model.lattice(0.06);
  EXPECT_EQ(sections.size(), static_cast<std::size_t>(p.basic_sections + 10));
  const core::Vec3 shaft = model.tangent(0.06);
  for (const auto& s : sections) {
    if (s.centre.z() > 0.06) {
      EXPECT_NEAR(s.centre.y(), p.curvature * s.centre.z() * s.centre.z(),
                  1e-15);  // on the parabola
    } else {
      EXPECT_LT((s.centre - model.centre_line(0.06)).cross(shaft).norm(),
                1e-12);  // on the straight shaft
    }
    ASSERT_EQ(s.points.size(), static_cast<std::size_t>(p.points_per_section));
    for (const auto& q : s.points) {
      EXPECT_NEAR((q - s.centre).norm(), s.radius, 1e-15);
      EXPECT_NEAR((q - s.centre).dot(s.normal), 0.0, 1e-15);  // sections normal to the centre line
    }
    if (s.centre.z() <= 0.06) {
      EXPECT_EQ(s.radius, p.endoscope_radius);
    }
    if (s.centre.z() >= 0.06 + p.transition_length) {
      EXPECT_EQ(s.radius, p.radius);
    }
  }
  // The moving deformation narrows monotonically ahead of the tip.
  double previous = p.endoscope_radius;
  for (const auto& s : sections) {
    if (s.centre.z() <= 0.06) continue;
    EXPECT_LE(s.radius, previous);
    previous = s.radius;
  }
}

TEST(UrethraModel, coulomb_and_viscous_friction_oppose_insertion_and_grow_with_depth) {
  const UrethraModel model;
  const auto& p = model.parameters();
  const UrethraFeedback shallow = model.feedback(on_centre_line(model, 0.03, 0.01));
  const UrethraFeedback deep = model.feedback(on_centre_line(model, 0.12, 0.01));
  EXPECT_GT(deep.normal_force, shallow.normal_force);
  // Purely axial sliding: |F1| = μ N and F2 = −b_V V.
  EXPECT_NEAR(deep.coulomb_friction, -p.friction * deep.normal_force, 1e-12);
  EXPECT_NEAR(deep.viscous_friction, -p.viscous_friction * 0.01, 1e-15);
  EXPECT_LT(deep.wall_resistance, 0.0);  // the narrowing wall ahead pushes back
  // Withdrawing reverses the friction.
  EXPECT_NEAR(model.feedback(on_centre_line(model, 0.12, -0.01)).coulomb_friction,
              -deep.coulomb_friction, 1e-12);
  // Along the axis: F_re has no x component and points back along the shaft.
  EXPECT_EQ(deep.force.x(), 0.0);
  EXPECT_LT(deep.force.z(), 0.0);
}

TEST(UrethraModel, torques_vanish_on_the_centre_line_and_restore_deviations) {
  const UrethraModel model;
  const UrethraFeedback centred = model.feedback(on_centre_line(model, 0.1));
  EXPECT_NEAR(centred.torque_x, 0.0, 1e-15);
  EXPECT_NEAR(centred.torque_y, 0.0, 1e-15);
  EXPECT_NEAR(centred.torque_z, 0.0, 1e-15);
  EndoscopeState raised = on_centre_line(model, 0.1);
  raised.tip.y() += 0.005;  // tip lifted off the centre line: the bladder spring pulls it back
  raised.pitch += 0.1;      // and tilted up: the tip spring turns it back
  EXPECT_LT(model.feedback(raised).torque_x, 0.0);
  EndoscopeState turned = on_centre_line(model, 0.1);
  turned.yaw = 0.2;
  EXPECT_LT(model.feedback(turned).torque_y, 0.0);
  // Outside the body (free part) the tip springs are slack.
  EndoscopeState outside = on_centre_line(model, 0.02);
  outside.yaw = 0.2;
  EXPECT_EQ(model.feedback(outside).torque_y, 0.0);
}

TEST(UrethraModel, spinning_the_scope_meets_coulomb_and_viscous_torque) {
  const UrethraModel model;
  const auto& p = model.parameters();
  const UrethraFeedback spin = model.feedback(on_centre_line(model, 0.1, 0.0, 2.0));
  // Pure rotation: T1 = −μ N r, T2 = −b_ω ω (eq. 12–13).
  EXPECT_NEAR(
      spin.torque_z,
      -p.friction * spin.normal_force * p.endoscope_radius - p.viscous_torque_friction * 2.0,
      1e-15);
}

TEST(UrethraModel, warns_near_and_beyond_the_tissue_break_limits) {
  UrethraParameters p;
  p.break_force = 1.0;
  const UrethraModel model(p);
  const UrethraFeedback gentle = model.feedback(on_centre_line(model, 0.03, 0.001));
  EXPECT_LT(gentle.bar_force, p.warning_fraction);
  EXPECT_TRUE(gentle.warnings.empty());
  const UrethraFeedback hard = model.feedback(on_centre_line(model, 0.15, 0.5));
  EXPECT_GE(hard.bar_force, 1.0);
  ASSERT_FALSE(hard.warnings.empty());
  EXPECT_NE(hard.warnings.front().find("axial force exceeds the tissue-break limit"),
            std::string::npos);
  EXPECT_THROW(UrethraModel(UrethraParameters{.radius = -1.0}), core::UsageError);
}

}  // namespace
}  // namespace viscera::sim

namespace viscera::sim {
namespace {

TEST(UrethraModel, bezier_surface_passes_through_the_lattice_and_faces_outward) {
  const UrethraModel model;
  const double tip = 0.06;
  const auto sections = model.lattice(tip);
  const core::SurfaceMesh wall = model.surface(tip, 3, 2);
  const std::size_t columns = static_cast<std::size_t>(model.parameters().points_per_section) * 3;
  // Row 2·s, column 3·i is lattice point i of section s.
  for (std::size_t s = 0; s < sections.size(); ++s)
    for (std::size_t i = 0; i < sections[s].points.size(); ++i) {
      EXPECT_TRUE(wall.vertices[(2 * s) * columns + 3 * i].isApprox(sections[s].points[i], 1e-12))
          << s << " " << i;
    }
  // Outward: at the lattice rows the normals point away from the section centre.
  for (std::size_t s = 0; s < sections.size(); ++s)
    for (std::size_t c = 0; c < columns; ++c) {
      const std::size_t v = (2 * s) * columns + c;
      EXPECT_GT(wall.normals[v].dot(wall.vertices[v] - sections[s].centre), 0.0) << v;
    }
  EXPECT_EQ(wall.triangles.size(), 2 * columns * (2 * (sections.size() - 1)));
}

}  // namespace
}  // namespace viscera::sim

namespace viscera::sim {
namespace {

TEST(UrethraModel, an_endoscope_off_the_centre_line_drags_the_tube_but_not_the_bladder_entrance) {
  const UrethraModel model;
  const auto& p = model.parameters();
  EndoscopeState scope;
  scope.tip = model.centre_line(0.07) + core::Vec3(0.0, 0.004, 0.0);  // 4 mm above the centre line
  scope.pitch = std::atan(2.0 * p.curvature * 0.07) + 0.15;           // and tilted up
  const auto sections = model.lattice(scope);
  const core::Vec3 axis(0.0, std::sin(scope.pitch), std::cos(scope.pitch));
  for (const auto& s : sections) {
    if (s.centre.z() <= 0.07) {
      // Behind the tip: on the straight shaft, normal to it.
      EXPECT_LT((s.centre - scope.tip).cross(axis).norm(), 1e-12);
      EXPECT_TRUE(s.normal.isApprox(axis, 1e-12));
    }
    for (const auto& q : s.points)
      EXPECT_NEAR((q - s.centre).dot(s.normal), 0.0, 1e-12);
  }
  // The bladder entrance stays put; the first section beyond the moving deformation carries
  // nearly the whole offset.
  EXPECT_TRUE(sections.back().centre.isApprox(model.centre_line(p.length), 1e-12));
  const auto first_ahead = std::find_if(
      sections.begin(), sections.end(),
      [&](const UrethraSection& s) { return s.centre.z() >= 0.07 + p.transition_length; });
  ASSERT_NE(first_ahead, sections.end());
  EXPECT_GT(first_ahead->centre.y() - model.centre_line(first_ahead->centre.z()).y(), 0.003);
  // On the centre line the general lattice is the plain one.
  EndoscopeState on_line;
  on_line.tip = model.centre_line(0.07);
  on_line.pitch = std::atan(2.0 * p.curvature * 0.07);
  const auto plain = model.lattice(0.07);
  const auto general = model.lattice(on_line);
  ASSERT_EQ(plain.size(), general.size());
  for (std::size_t i = 0; i < plain.size(); ++i)
    EXPECT_TRUE(plain[i].centre.isApprox(general[i].centre, 1e-12));
}

}  // namespace
}  // namespace viscera::sim
