#include "core/primitives/pipe_primitive.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/curves/arc_length.h"
#include "core/curves/rotation_minimizing_frames.h"
#include "core/error.h"

namespace viscera::core {

std::string to_string(PipeCap cap) {
  switch (cap) {
    case PipeCap::Flat:
      return "flat";
    case PipeCap::Round:
      return "round";
    case PipeCap::Open:
      return "open";
  }
  return "flat";
}

PipeCap pipe_cap_from_string(const std::string& name) {
  if (name == "flat") return PipeCap::Flat;
  if (name == "round") return PipeCap::Round;
  if (name == "open") return PipeCap::Open;
  throw UsageError("pipe cap must be flat, round or open, not \"" + name + "\"");
}

void check_pipe(const PipePrimitive& pipe, const std::string& what) {
  if (pipe.points.size() < 2)
    throw UsageError(what + ": a pipe needs at least 2 centre-line points");
  if (pipe.radii.size() != pipe.points.size()) {
    throw UsageError(what + ": a pipe needs one radius per centre-line point (" +
                     std::to_string(pipe.points.size()) + "), not " +
                     std::to_string(pipe.radii.size()));
  }
  for (std::size_t i = 0; i < pipe.points.size(); ++i) {
    if (!pipe.points[i].allFinite())
      throw UsageError(what + ": centre-line point " + std::to_string(i) + " is not finite");
    if (!(pipe.radii[i] > 0.0) || !std::isfinite(pipe.radii[i])) {
      throw UsageError(what + ": radius " + std::to_string(i) + " must be positive");
    }
    if (i > 0 && !((pipe.points[i] - pipe.points[i - 1]).norm() > 0.0)) {
      throw UsageError(what + ": centre-line points " + std::to_string(i - 1) + " and " +
                       std::to_string(i) + " coincide");
    }
  }
  if (pipe.ring_segments < 3 || pipe.ring_segments > 1024)
    throw UsageError(what + ": ring segments must be in [3, 1024]");
  if (pipe.axial_spacing < 0.0 || !std::isfinite(pipe.axial_spacing))
    throw UsageError(what + ": axial spacing must not be negative");
}

CubicCurve pipe_centre_line(const PipePrimitive& pipe) {
  check_pipe(pipe, "pipe");
  return catmull_rom_curve(pipe.points, KnotSpacing::ChordLength, false);
}

double pipe_radius_at(const PipePrimitive& pipe, const CubicCurve& centre_line, double t) {
  // The radii as the x of points, interpolated with the centre line's knots so that radius and
  // position share one parametrisation.
  std::vector<Vec3> values;
  for (const double r : pipe.radii)
    values.emplace_back(r, 0.0, 0.0);
  const CubicCurve profile(catmull_rom_bezier_net(values, centre_line.knot_gaps(), false),
                           centre_line.knot_gaps(), false);
  const double smallest = *std::min_element(pipe.radii.begin(), pipe.radii.end());
  return std::max(profile.point(t).x(), 0.1 * smallest);
}

namespace {

/// Builds the ring vertices and side triangles, then closes the ends.
class PipeSweep {
 public:
  PipeSweep(const PipePrimitive& pipe, const PipeSweepOptions& options)
      : pipe_(pipe), n_(pipe.ring_segments) {
    const CubicCurve centre = pipe_centre_line(pipe);
    const ArcLengthTable table(centre);
    length_ = table.length();
    double mean_radius = 0.0;
    for (const double r : pipe.radii)
      mean_radius += r / static_cast<double>(pipe.radii.size());
    spacing_ =
        pipe.axial_spacing > 0.0 ? pipe.axial_spacing : 2.0 * std::numbers::pi * mean_radius / n_;
    const int intervals = std::max(1, static_cast<int>(std::ceil(length_ / spacing_ - 1e-9)));
    const auto parameters = even_arc_length_parameters(table, intervals);
    frames_ = rotation_minimizing_frames(centre, parameters, Vec3::UnitZ());
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      radii_.push_back(pipe_radius_at(pipe, centre, parameters[i]));
      arc_.push_back(length_ * static_cast<double>(i) / intervals);
    }
    if (options.start_extension > 0.0) {
      CurveFrame back = frames_.front();
      back.origin -= options.start_extension * back.tangent;
      frames_.insert(frames_.begin(), back);
      radii_.insert(radii_.begin(), radii_.front());
      arc_.insert(arc_.begin(), -options.start_extension);
    }
  }

  SurfaceMesh build() {
    for (std::size_t i = 0; i < frames_.size(); ++i)
      add_ring(frames_[i], radii_[i], 0.0, arc_[i]);
    for (int i = 0; i + 1 < static_cast<int>(frames_.size()); ++i) {
      for (int k = 0; k < n_; ++k) {
        const int a = ring(i, k), b = ring(i, (k + 1) % n_), c = ring(i + 1, k),
                  d = ring(i + 1, (k + 1) % n_);
        mesh_.triangles.push_back({a, b, c});
        mesh_.triangles.push_back({b, d, c});
      }
    }
    close_end(pipe_.start_cap, 0, -1.0);
    close_end(pipe_.end_cap, static_cast<int>(frames_.size()) - 1, 1.0);
    mesh_.vertex_attributes["pipe_s"] = std::move(s_);
    compute_vertex_normals(mesh_);
    return std::move(mesh_);
  }

 private:
  int ring(int i, int k) const { return i * n_ + k; }

  /// A ring of n_ vertices at `frame`, radius `r`, shifted by `shift` m along the tangent.
  int add_ring(const CurveFrame& frame, double r, double shift, double s) {
    const int first = static_cast<int>(mesh_.vertices.size());
    for (int k = 0; k < n_; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / n_;
      mesh_.vertices.push_back(
          frame.origin + shift * frame.tangent +
          r * (std::cos(angle) * frame.normal + std::sin(angle) * frame.binormal));
      mesh_.uvs.emplace_back(static_cast<double>(k) / n_, std::clamp(s / length_, 0.0, 1.0));
      s_.push_back(s);
    }
    return first;
  }

  /// Closes ring `end` with inner rings towards a centre or pole. `side` is −1 at the start
  /// (outward = −tangent) and +1 at the end. The side triangles use the start ring's edges as
  /// k → k+1 and the end ring's as k+1 → k, so the cap takes the opposite directions.
  void close_end(PipeCap cap, int end, double side) {
    if (cap == PipeCap::Open) return;
    const CurveFrame& frame = frames_[static_cast<std::size_t>(end)];
    const double r = radii_[static_cast<std::size_t>(end)], s = arc_[static_cast<std::size_t>(end)];
    const int steps = std::max(
        1, static_cast<int>(
               std::lround((cap == PipeCap::Round ? 0.5 * std::numbers::pi : 1.0) * r / spacing_)));
    int outer = ring(end, 0);
    for (int m = 1; m < steps; ++m) {
      const double f = static_cast<double>(m) / steps;
      const double radius =
          cap == PipeCap::Round ? r * std::cos(0.5 * std::numbers::pi * f) : r * (1.0 - f);
      const double shift =
          cap == PipeCap::Round ? side * r * std::sin(0.5 * std::numbers::pi * f) : 0.0;
      const int inner = add_ring(frame, radius, shift, s);
      for (int k = 0; k < n_; ++k) {
        const int o0 = outer + k, o1 = outer + (k + 1) % n_, i0 = inner + k,
                  i1 = inner + (k + 1) % n_;
        if (side < 0.0) {
          mesh_.triangles.push_back({o1, o0, i0});
          mesh_.triangles.push_back({o1, i0, i1});
        } else {
          mesh_.triangles.push_back({o0, o1, i1});
          mesh_.triangles.push_back({o0, i1, i0});
        }
      }
      outer = inner;
    }
    const int centre = static_cast<int>(mesh_.vertices.size());
    mesh_.vertices.push_back(frame.origin +
                             (cap == PipeCap::Round ? side * r : 0.0) * frame.tangent);
    mesh_.uvs.emplace_back(0.5, side < 0.0 ? 0.0 : 1.0);
    s_.push_back(s);
    for (int k = 0; k < n_; ++k) {
      const int o0 = outer + k, o1 = outer + (k + 1) % n_;
      if (side < 0.0) {
        mesh_.triangles.push_back({o1, o0, centre});
      } else {
        mesh_.triangles.push_back({o0, o1, centre});
      }
    }
  }

  const PipePrimitive& pipe_;
  int n_;
  double length_ = 0.0, spacing_ = 0.0;
  std::vector<CurveFrame> frames_;
  std::vector<double> radii_, arc_;
  SurfaceMesh mesh_;
  std::vector<double> s_;
};

}  // namespace

SurfaceMesh tessellate_pipe(const PipePrimitive& pipe, const PipeSweepOptions& options) {
  check_pipe(pipe, "pipe");
  if (options.start_extension < 0.0) throw UsageError("pipe start extension must not be negative");
  return PipeSweep(pipe, options).build();
}

}  // namespace viscera::core
