#include "textures/vessel_painter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "core/lsystem/lsystem.h"
#include "core/random.h"
#include "textures/parallel_rows.h"

namespace viscera::textures {

std::vector<core::TurtleSegment> grow_vessel_layer(const VesselLayerSpec& spec, int width,
                                                   int height, std::uint64_t seed) {
  const core::Lsystem grammar = core::Lsystem::parse(spec.grammar, "vessel grammar");
  const double step_px = spec.step * width;
  const double width_px = spec.width * width;
  std::vector<core::TurtleSegment> strokes;
  for (int tree = 0; tree < spec.trees; ++tree) {
    core::Rng rng = core::Rng::for_stream(seed, static_cast<std::uint64_t>(tree));
    const core::Vec3 root(rng.uniform(0.0, width), rng.uniform(0.0, height), 0.0);
    const double degrees =
        spec.direction + rng.uniform(-spec.direction_jitter, spec.direction_jitter);
    const double a = degrees * std::numbers::pi / 180.0;
    core::TurtleOptions turtle;
    turtle.heading = core::Vec3(std::cos(a), std::sin(a), 0.0);
    turtle.left = core::Vec3(-std::sin(a), std::cos(a), 0.0);
    turtle.angle = spec.angle;
    turtle.angle_jitter = spec.angle_jitter;
    turtle.subdivisions = spec.subdivisions;
    turtle.wiggle = spec.wiggle;
    turtle.width_factor = spec.width_factor;
    turtle.depth_step = spec.depth_step;
    turtle.taper = spec.taper * spec.step;  // per grammar unit of length
    const std::uint64_t derivation_seed = rng.next_u64();
    turtle.seed = rng.next_u64();
    const int offset = static_cast<int>(strokes.size());
    for (auto s :
         core::interpret_turtle(grammar.derive(spec.generations, derivation_seed), turtle)) {
      s.start = root + step_px * s.start;
      s.end = root + step_px * s.end;
      s.start_width *= width_px;
      s.end_width *= width_px;
      if (s.parent >= 0) s.parent += offset;
      strokes.push_back(s);
    }
  }
  return strokes;
}

namespace {

/// The x interval [lo, hi] where the horizontal line at height y meets the capsule of radius r
/// around segment a-b; empty (lo > hi) when it misses. The capsule is convex, so the interval is
/// the hull of the line's intersections with the two end discs and the swept rectangle.
void capsule_row_span(double ax, double ay, double bx, double by, double r, double y, double& lo,
                      double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (const auto& [cx, cy] : {std::pair{ax, ay}, std::pair{bx, by}}) {
    const double dy = y - cy;
    if (std::abs(dy) <= r) {
      const double half = std::sqrt(r * r - dy * dy);
      lo = std::min(lo, cx - half);
      hi = std::max(hi, cx + half);
    }
  }
  const double dx = bx - ax, dy = by - ay;
  const double length = std::sqrt(dx * dx + dy * dy);
  if (length == 0.0) return;
  const double nx = -dy / length * r, ny = dx / length * r;
  const double corners[4][2] = {
      {ax + nx, ay + ny}, {bx + nx, by + ny}, {bx - nx, by - ny}, {ax - nx, ay - ny}};
  for (int e = 0; e < 4; ++e) {
    const double* p = corners[e];
    const double* q = corners[(e + 1) % 4];
    if ((p[1] <= y && q[1] >= y) || (q[1] <= y && p[1] >= y)) {
      const double x = p[1] == q[1] ? p[0] : p[0] + (y - p[1]) / (q[1] - p[1]) * (q[0] - p[0]);
      lo = std::min({lo, x, p[1] == q[1] ? q[0] : x});
      hi = std::max({hi, x, p[1] == q[1] ? q[0] : x});
    }
  }
}

/// Radius beyond which a stroke leaves no ink: half its widest width (at least one pixel wide)
/// plus one pixel for the anti-aliasing ramp and pixel centres.
double stroke_reach(const core::TurtleSegment& s) {
  return 0.5 * std::max({s.start_width, s.end_width, 1.0}) + 1.0;
}

}  // namespace

VesselRasterizer::VesselRasterizer(std::vector<core::TurtleSegment> strokes, int width, int height)
    : strokes_(std::move(strokes)),
      bands_(static_cast<std::size_t>((height + kBandRows - 1) / kBandRows)),
      width_(width),
      height_(height) {
  for (std::size_t i = 0; i < strokes_.size(); ++i) {
    const auto& s = strokes_[i];
    const double reach = stroke_reach(s);
    const int y0 =
        std::max(0, static_cast<int>(std::floor(std::min(s.start.y(), s.end.y()) - reach)));
    const int y1 =
        std::min(height - 1, static_cast<int>(std::ceil(std::max(s.start.y(), s.end.y()) + reach)));
    for (int band = y0 / kBandRows; y0 <= y1 && band <= y1 / kBandRows; ++band) {
      bands_[band].push_back(static_cast<int>(i));
    }
  }
}

void VesselRasterizer::paint_rows(int row_begin, int row_end, float* coverage_rows,
                                  float* depth_rows) const {
  row_begin = std::max(row_begin, 0);
  row_end = std::min(row_end, height_);
  if (row_begin >= row_end) return;
  for (int band = row_begin / kBandRows; band <= (row_end - 1) / kBandRows; ++band) {
    for (const int index : bands_[band]) {
      const auto& s = strokes_[index];
      const double reach = stroke_reach(s);
      const int y0 =
          std::max({row_begin, band * kBandRows,
                    static_cast<int>(std::floor(std::min(s.start.y(), s.end.y()) - reach))});
      const int y1 =
          std::min({row_end - 1, band * kBandRows + kBandRows - 1,
                    static_cast<int>(std::ceil(std::max(s.start.y(), s.end.y()) + reach))});
      const double ax = s.start.x(), ay = s.start.y();
      const double dx = s.end.x() - ax, dy = s.end.y() - ay;
      const double length2 = dx * dx + dy * dy;
      const auto stroke_depth = static_cast<float>(s.depth);
      for (int y = y0; y <= y1; ++y) {
        double lo = 0.0, hi = 0.0;
        capsule_row_span(ax, ay, s.end.x(), s.end.y(), reach, y + 0.5, lo, hi);
        const int x0 = std::max(0, static_cast<int>(std::floor(lo - 0.5)));
        const int x1 = std::min(width_ - 1, static_cast<int>(std::ceil(hi - 0.5)));
        const double py = y + 0.5 - ay;
        float* coverage = coverage_rows + static_cast<std::size_t>(y - row_begin) * width_;
        float* depth = depth_rows + static_cast<std::size_t>(y - row_begin) * width_;
        for (int x = x0; x <= x1; ++x) {
          const double px = x + 0.5 - ax;
          const double t =
              length2 > 0.0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
          const double ex = px - t * dx, ey = py - t * dy;
          const double w = s.start_width + t * (s.end_width - s.start_width);
          // A stroke thinner than a pixel keeps a one-pixel footprint with proportionally less ink.
          const double footprint = std::max(w, 1.0);
          const auto c = static_cast<float>(
              std::clamp(0.5 * footprint - std::sqrt(ex * ex + ey * ey) + 0.5, 0.0, 1.0) *
              std::min(w, 1.0));
          if (c > coverage[x] || (c == coverage[x] && c > 0.0f && stroke_depth < depth[x])) {
            coverage[x] = c;
            depth[x] = stroke_depth;
          }
        }
      }
    }
  }
}

VesselLayerImage paint_vessels(const std::vector<core::TurtleSegment>& strokes, int width,
                               int height, int threads) {
  const VesselRasterizer rasterizer(strokes, width, height);
  VesselLayerImage layer;
  layer.width = width;
  layer.height = height;
  layer.coverage.assign(static_cast<std::size_t>(width) * height, 0.0f);
  layer.depth.assign(layer.coverage.size(), 0.0f);
  parallel_rows(
      height,
      [&](int begin, int end) {
        const std::size_t offset = static_cast<std::size_t>(begin) * width;
        rasterizer.paint_rows(begin, end, layer.coverage.data() + offset,
                              layer.depth.data() + offset);
      },
      threads);
  return layer;
}

}  // namespace viscera::textures
