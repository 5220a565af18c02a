#include "simulator/cutting/cut_surface.h"

#include <cmath>
#include <sstream>
#include <string>

#include "core/error.h"

namespace viscera::sim::cutting {
namespace {

using core::InputError;
using core::Vec3;

bool finite(const Vec3& v) {
  return v.allFinite();
}

std::string describe(const Vec3& v) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ") m";
  return s.str();
}

// Adds the two triangles of the quad a-b-c-d (counter-clockwise), skipping degenerate ones.
void add_quad(CutSurface& surface, int a, int b, int c, int d) {
  const auto area = [&](int i, int j, int k) {
    const Vec3& p = surface.vertices[i];
    return (surface.vertices[j] - p).cross(surface.vertices[k] - p).norm();
  };
  const Vec3 diagonal = surface.vertices[c] - surface.vertices[a];
  const double scale = diagonal.squaredNorm() + 1e-300;
  if (area(a, b, c) > 1e-12 * scale) surface.triangles.push_back({a, b, c});
  if (area(a, c, d) > 1e-12 * scale) surface.triangles.push_back({a, c, d});
}

}  // namespace

std::vector<Vec3> loop_points(const LoopElectrode& loop, const LoopPose& pose) {
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(loop.segments) + 1);
  for (int i = 0; i <= loop.segments; ++i) {
    const double theta = loop.arc_radians * (static_cast<double>(i) / loop.segments - 0.5);
    const Vec3 local(loop.radius * std::sin(theta), -loop.radius * std::cos(theta), 0.0);
    points.push_back(pose.position + pose.rotation * local);
  }
  return points;
}

CutSurface swept_loop_surface(const LoopElectrode& loop, const std::vector<LoopPose>& sweep) {
  if (!std::isfinite(loop.radius) || loop.radius <= 0.0) {
    throw InputError("the loop electrode's radius is " + std::to_string(loop.radius) +
                     " m; a loop needs a positive, finite radius to cut");
  }
  if (!std::isfinite(loop.arc_radians) || loop.arc_radians <= 0.0 ||
      loop.arc_radians > 2.0 * M_PI + 1e-12) {
    throw InputError("the loop electrode's arc is " + std::to_string(loop.arc_radians) +
                     " rad; it must lie in (0, 2π]");
  }
  if (loop.segments < 2) {
    throw InputError("the loop electrode has " + std::to_string(loop.segments) +
                     " wire segments; at least 2 are needed to form a loop");
  }
  if (sweep.size() < 2) {
    throw InputError("the loop sweep has " + std::to_string(sweep.size()) +
                     " pose(s); a cut needs the loop at two or more places along its path");
  }
  double travel = 0.0;
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    const LoopPose& pose = sweep[k];
    if (!finite(pose.position) || !pose.rotation.allFinite()) {
      throw InputError("loop sweep pose " + std::to_string(k) +
                       " has a non-finite position or rotation");
    }
    if (!(pose.rotation.transpose() * pose.rotation).isApprox(core::Mat3::Identity(), 1e-6)) {
      throw InputError("loop sweep pose " + std::to_string(k) +
                       " has a rotation that is not orthonormal");
    }
    travel = std::max(travel, (pose.position - sweep.front().position).norm());
  }
  if (travel < 1e-3 * loop.radius) {
    throw InputError("the loop sweep does not move the loop (it stays within " +
                     std::to_string(travel) + " m of " + describe(sweep.front().position) +
                     "), so it sweeps no cut surface");
  }
  std::vector<std::vector<Vec3>> wires;
  wires.reserve(sweep.size());
  for (const LoopPose& pose : sweep)
    wires.push_back(loop_points(loop, pose));
  return swept_wire_surface(wires);
}

CutSurface swept_wire_surface(const std::vector<std::vector<Vec3>>& samples) {
  if (samples.size() < 2) {
    throw InputError("the electrode's sweep has " + std::to_string(samples.size()) +
                     " sample(s); a cut needs the wire at two or more places along its path");
  }
  const std::size_t row = samples.front().size();
  if (row < 2) throw InputError("the electrode's wire has fewer than two points");
  CutSurface surface;
  surface.vertices.reserve(row * samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (samples[k].size() != row) {
      throw InputError("sample " + std::to_string(k) + " of the electrode's sweep has " +
                       std::to_string(samples[k].size()) + " wire points, the first has " +
                       std::to_string(row));
    }
    for (const Vec3& p : samples[k]) {
      if (!finite(p)) {
        throw InputError("sample " + std::to_string(k) +
                         " of the electrode's sweep has a non-finite wire point");
      }
      surface.vertices.push_back(p);
    }
  }
  const int r = static_cast<int>(row);
  for (int k = 0; k + 1 < static_cast<int>(samples.size()); ++k) {
    for (int i = 0; i + 1 < r; ++i) {
      const int a = k * r + i;
      add_quad(surface, a, a + 1, a + 1 + r, a + r);
    }
  }
  if (surface.triangles.empty()) {
    throw InputError(
        "the electrode's sweep moves the wire only within its own line, so it sweeps no cut "
        "surface");
  }
  return surface;
}

CutSurface planar_cut_surface(const Vec3& center, const Vec3& normal, const Vec3& u_axis,
                              double half_width, double half_height, int divisions) {
  if (!finite(center) || !finite(normal) || !finite(u_axis) || !std::isfinite(half_width) ||
      !std::isfinite(half_height)) {
    throw InputError("the planar cut has a non-finite centre, normal, axis or extent");
  }
  if (normal.norm() < 1e-12) throw InputError("the planar cut's normal is zero");
  const Vec3 n = normal.normalized();
  const Vec3 u_raw = u_axis - u_axis.dot(n) * n;
  if (u_raw.norm() < 1e-9 * std::max(1.0, u_axis.norm())) {
    throw InputError("the planar cut's in-plane axis is parallel to its normal");
  }
  if (half_width <= 0.0 || half_height <= 0.0) {
    throw InputError("the planar cut's extents must be positive (half width " +
                     std::to_string(half_width) + " m, half height " + std::to_string(half_height) +
                     " m)");
  }
  if (divisions < 1) throw InputError("the planar cut needs at least one division");
  const Vec3 u = u_raw.normalized();
  const Vec3 v = n.cross(u);
  CutSurface surface;
  for (int j = 0; j <= divisions; ++j) {
    for (int i = 0; i <= divisions; ++i) {
      const double s = 2.0 * i / divisions - 1.0;
      const double t = 2.0 * j / divisions - 1.0;
      surface.vertices.push_back(center + s * half_width * u + t * half_height * v);
    }
  }
  const int row = divisions + 1;
  for (int j = 0; j < divisions; ++j) {
    for (int i = 0; i < divisions; ++i)
      add_quad(surface, j * row + i, j * row + i + 1, (j + 1) * row + i + 1, (j + 1) * row + i);
  }
  return surface;
}

CutSurface scissor_cut_surface(const Vec3& hinge, const Vec3& tip_a, const Vec3& tip_b,
                               int divisions) {
  if (!finite(hinge) || !finite(tip_a) || !finite(tip_b)) {
    throw InputError("the scissor cut has a non-finite hinge or blade tip");
  }
  if (divisions < 1) throw InputError("the scissor cut needs at least one division");
  const Vec3 a = tip_a - hinge;
  const Vec3 b = tip_b - hinge;
  if (a.norm() < 1e-9 || b.norm() < 1e-9 || a.cross(b).norm() < 1e-6 * a.norm() * b.norm()) {
    throw InputError("the scissor blades from hinge " + describe(hinge) +
                     " are of zero length or collinear, so the jaws close on no surface");
  }
  // Rows of points between the blades at growing distance from the hinge.
  CutSurface surface;
  surface.vertices.push_back(hinge);
  std::vector<int> previous{0};
  for (int r = 1; r <= divisions; ++r) {
    std::vector<int> current;
    const double f = static_cast<double>(r) / divisions;
    for (int i = 0; i <= r; ++i) {
      const double g = static_cast<double>(i) / r;
      current.push_back(static_cast<int>(surface.vertices.size()));
      surface.vertices.push_back(hinge + f * ((1.0 - g) * a + g * b));
    }
    for (int i = 0; i < r; ++i) {
      surface.triangles.push_back({previous[i], current[i], current[i + 1]});
      if (i + 1 < r) surface.triangles.push_back({previous[i], current[i + 1], previous[i + 1]});
    }
    previous = std::move(current);
  }
  return surface;
}

}  // namespace viscera::sim::cutting
