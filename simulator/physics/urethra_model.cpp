#include "simulator/physics/urethra_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/curves/catmull_rom.h"
#include "core/error.h"

namespace viscera::sim {

UrethraModel::UrethraModel(const UrethraParameters& parameters) : p_(parameters) {
  if (p_.basic_sections < 2 || p_.points_per_section < 3)
    throw core::UsageError("urethra needs ≥ 2 sections of ≥ 3 points");
  if (!(p_.radius > 0.0) || !(p_.endoscope_radius >= p_.radius) || !(p_.length > 0.0) ||
      !(p_.transition_length > 0.0)) {
    throw core::UsageError(
        "urethra radii, length and transition must be positive, endoscope ≥ lumen");
  }
  for (int j = 0; j < p_.basic_sections; ++j)
    section_z_.push_back(p_.length * j / (p_.basic_sections - 1));
}

core::Vec3 UrethraModel::centre_line(double z) const {
  return {0.0, p_.curvature * z * z, z};
}

core::Vec3 UrethraModel::tangent(double z) const {
  return core::Vec3(0.0, 2.0 * p_.curvature * z, 1.0).normalized();
}

double UrethraModel::widened_radius(double ahead) const {
  if (ahead <= 0.0) return p_.endoscope_radius;
  if (ahead >= p_.transition_length) return p_.radius;
  // Half a cosine wave: tangent-continuous with the endoscope at the tip and with the
  // undeformed lumen at the end of the moving deformation (seed 002 §3.2).
  return p_.radius + (p_.endoscope_radius - p_.radius) * 0.5 *
                         (1.0 + std::cos(std::numbers::pi * ahead / p_.transition_length));
}

double UrethraModel::insertion_fraction(double tip_z) const {
  return std::clamp((tip_z - p_.free_length) / (p_.length - p_.free_length), 0.0, 1.0);
}

namespace {

/// The endoscope's shaft direction for pitch θx (towards +y) and yaw θy (towards +x).
core::Vec3 shaft_axis(double pitch, double yaw) {
  return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

/// `v` turned about the x axis by `angle` rad.
core::Vec3 turned_about_x(const core::Vec3& v, double angle) {
  return {v.x(), std::cos(angle) * v.y() - std::sin(angle) * v.z(),
          std::sin(angle) * v.y() + std::cos(angle) * v.z()};
}

}  // namespace

std::vector<UrethraSection> UrethraModel::lattice(double tip_z) const {
  EndoscopeState on_line;
  on_line.tip = centre_line(tip_z);
  on_line.pitch = std::atan(2.0 * p_.curvature * tip_z);
  return lattice(on_line);
}

std::vector<UrethraSection> UrethraModel::lattice(const EndoscopeState& e) const {
  const double tip_z = e.tip.z();
  const core::Vec3 axis = shaft_axis(e.pitch, e.yaw);
  const double offset = e.tip.y() - centre_line(tip_z).y();             // dy
  const double tilt = e.pitch - std::atan(2.0 * p_.curvature * tip_z);  // dθx
  std::vector<double> zs = section_z_;
  constexpr int kMovingSections = 10;  // seed 002: ten subsections
  for (int k = 1; k <= kMovingSections; ++k) {
    const double z = tip_z + p_.transition_length * k / kMovingSections;
    if (z > 0.0 && z < p_.length) zs.push_back(z);
  }
  std::sort(zs.begin(), zs.end());
  // Basic sections beyond the moving deformation, counted to share out offset and tilt.
  const double downstream_from = tip_z + p_.transition_length;
  const auto downstream = static_cast<int>(std::count_if(
      section_z_.begin(), section_z_.end(), [&](double z) { return z >= downstream_from; }));
  int downstream_index = 0;
  std::vector<UrethraSection> sections;
  for (const double z : zs) {
    UrethraSection s;
    s.radius = widened_radius(z - tip_z);
    if (z <= tip_z && axis.z() > 1e-9) {
      // Behind the tip the urethra takes the rigid shaft's shape.
      s.centre = e.tip - axis * ((tip_z - z) / axis.z());
      s.normal = axis;
    } else if (z < downstream_from) {
      // The moving deformation blends from the shaft to the undeformed tube.
      const double blend =
          0.5 * (1.0 + std::cos(std::numbers::pi * (z - tip_z) / p_.transition_length));
      s.centre = centre_line(z) + core::Vec3(0.0, offset, 0.0);
      s.normal = (blend * axis + (1.0 - blend) * turned_about_x(tangent(z), tilt)).normalized();
    } else {
      // Ahead: dy falls to zero at the bladder entrance, dθx to dθx / K there.
      const bool basic = std::find(section_z_.begin(), section_z_.end(), z) != section_z_.end();
      const int k = basic ? ++downstream_index : std::max(1, downstream_index);
      const double share = downstream > 0 ? static_cast<double>(downstream - k) / downstream : 0.0;
      const double turn =
          downstream > 0 ? tilt * static_cast<double>(downstream - k + 1) / downstream : 0.0;
      s.centre = centre_line(z) + core::Vec3(0.0, offset * share, 0.0);
      s.normal = turned_about_x(tangent(z), turn);
    }
    const core::Vec3 u = core::Vec3::UnitX();
    const core::Vec3 v = s.normal.cross(u).normalized();
    const core::Vec3 w = v.cross(s.normal);  // x direction made normal to the section's axis
    for (int i = 0; i < p_.points_per_section; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / p_.points_per_section;
      s.points.push_back(s.centre + s.radius * (std::cos(angle) * w + std::sin(angle) * v));
    }
    sections.push_back(std::move(s));
  }
  return sections;
}

core::SurfaceMesh UrethraModel::surface(double tip_z, int around, int along) const {
  EndoscopeState on_line;
  on_line.tip = centre_line(tip_z);
  on_line.pitch = std::atan(2.0 * p_.curvature * tip_z);
  return surface(on_line, around, along);
}

core::SurfaceMesh UrethraModel::surface(const EndoscopeState& endoscope, int around,
                                        int along) const {
  if (around < 1 || along < 1)
    throw core::UsageError("urethra surface needs at least one sample per segment");
  const auto sections = lattice(endoscope);
  // Rings: each section's points interpolated around the lumen.
  std::vector<std::vector<core::Vec3>> rings;
  for (const auto& section : sections) {
    const core::CatmullRomSpline ring(section.points, core::KnotSpacing::ChordLength, true);
    std::vector<core::Vec3> samples;
    for (int s = 0; s < ring.segments(); ++s)
      for (int k = 0; k < around; ++k)
        samples.push_back(ring.evaluate(s, static_cast<double>(k) / around));
    rings.push_back(std::move(samples));
  }
  // Along the tube: one open curve per ring position through the successive rings.
  const std::size_t columns = rings.front().size();
  std::vector<std::vector<core::Vec3>> rows;  // rows[r][c]
  for (std::size_t c = 0; c < columns; ++c) {
    std::vector<core::Vec3> through;
    for (const auto& r : rings)
      through.push_back(r[c]);
    const core::CatmullRomSpline line(through, core::KnotSpacing::ChordLength, false);
    std::size_t r = 0;
    for (int s = 0; s < line.segments(); ++s) {
      for (int k = 0; k < along || (s == line.segments() - 1 && k == along); ++k, ++r) {
        if (rows.size() <= r) rows.emplace_back(columns);
        rows[r][c] = line.evaluate(s, static_cast<double>(k) / along);
      }
    }
  }
  core::SurfaceMesh mesh;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < columns; ++c) {
      mesh.vertices.push_back(rows[r][c]);
      mesh.uvs.emplace_back(static_cast<double>(c) / columns,
                            static_cast<double>(r) / (rows.size() - 1));
    }
  }
  const auto index = [columns](std::size_t r, std::size_t c) {
    return static_cast<int>(r * columns + c % columns);
  };
  for (std::size_t r = 0; r + 1 < rows.size(); ++r) {
    for (std::size_t c = 0; c < columns; ++c) {
      // Ring points run counter-clockwise about +z, rows run along +z: this winding faces out.
      mesh.triangles.push_back({index(r, c), index(r, c + 1), index(r + 1, c + 1)});
      mesh.triangles.push_back({index(r, c), index(r + 1, c + 1), index(r + 1, c)});
    }
  }
  core::compute_vertex_normals(mesh);
  return mesh;
}

UrethraFeedback UrethraModel::feedback(const EndoscopeState& e) const {
  UrethraFeedback out;
  const double tip_z = e.tip.z();
  const core::Vec3 axis = shaft_axis(e.pitch, e.yaw);
  const int springs = p_.points_per_section - 1;

  // Wall springs of the basic sections: stretched to the endoscope behind the tip, partly
  // within the moving deformation ahead of it. Their sum presses on the shaft (N); ahead of the
  // tip the sloping wall also pushes back along the axis (F3).
  for (const double z : section_z_) {
    const double ahead = z - tip_z;
    const double stretch = widened_radius(ahead) - p_.radius;
    if (stretch <= 0.0) continue;
    const double spring_force = springs * p_.spring_stiffness * stretch;
    out.normal_force += spring_force;
    if (ahead > 0.0) {
      const double slope = (p_.endoscope_radius - p_.radius) * 0.5 * std::numbers::pi /
                           p_.transition_length *
                           std::sin(std::numbers::pi * ahead / p_.transition_length);
      out.wall_resistance -= spring_force * slope / std::sqrt(1.0 + slope * slope);
    }
  }

  // Friction (eq. 7, 8, 12, 13): the tissue slides past the shaft axially and around it.
  const double axial_speed = e.velocity.dot(axis);
  const double around_speed = e.spin_rate * p_.endoscope_radius;  // V⊥ = ω r
  const double speed = std::sqrt(e.velocity.squaredNorm() + around_speed * around_speed);
  if (speed > 1e-12) {
    out.coulomb_friction = -p_.friction * out.normal_force * axial_speed / speed;
    out.torque_z = -p_.friction * out.normal_force * p_.endoscope_radius * around_speed / speed;
  }
  out.viscous_friction = -p_.viscous_friction * axial_speed;
  out.torque_z -= p_.viscous_torque_friction * e.spin_rate;

  const double along_axis =
      out.coulomb_friction + out.viscous_friction + out.wall_resistance;  // eq. 6
  out.force = along_axis * axis;
  out.force.x() = 0.0;  // only the y–z projections are fed to the device (seed 002 §5.1)

  // Tx: a rotational spring at the tip against leaving the centre line's direction, stiffening
  // with insertion, plus the bladder spring on the telescopic rod (eq. 9–10). Ty likewise for
  // turning out of the plane of symmetry.
  const double tip_stiffness = p_.tip_rotational_stiffness * insertion_fraction(tip_z);
  out.torque_x = -tip_stiffness * (e.pitch - std::atan(2.0 * p_.curvature * tip_z));
  const core::Vec3 bladder = centre_line(p_.length);
  const double run = tip_z - bladder.z();
  if (std::abs(run) > 1e-12) {
    const double reference =
        std::atan((p_.curvature * tip_z * tip_z - bladder.y()) / run);  // eq. 9
    const double actual = std::atan((e.tip.y() - bladder.y()) / run);   // eq. 10
    out.torque_x -= p_.bladder_rotational_stiffness * (actual - reference);
  }
  out.torque_y = -tip_stiffness * e.yaw;

  // Bars and warnings (seed 002 §5.2, Fig. 11).
  out.bar_force = std::abs(along_axis) / p_.break_force;
  out.bar_tx = std::abs(out.torque_x) / p_.break_torque;
  out.bar_ty = std::abs(out.torque_y) / p_.break_torque;
  out.bar_tz = std::abs(out.torque_z) / p_.break_torque;
  const auto warn = [&](double bar, const std::string& what) {
    if (bar >= 1.0) {
      out.warnings.push_back(what + " exceeds the tissue-break limit");
    } else if (bar >= p_.warning_fraction) {
      out.warnings.push_back(what + " near the tissue-break limit");
    }
  };
  warn(out.bar_force, "axial force");
  warn(out.bar_tx, "torque Tx");
  warn(out.bar_ty, "torque Ty");
  warn(out.bar_tz, "torque Tz");
  return out;
}

}  // namespace viscera::sim
