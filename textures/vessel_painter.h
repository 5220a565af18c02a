#pragma once
/// L-system vessel trees painted into textures (seed 001 §3.3): the turtle draws tapered strokes
/// whose opacity and colour fade with depth below the surface.

#include <cstdint>
#include <vector>

#include "core/lsystem/turtle.h"
#include "textures/texture_preset.h"

namespace viscera::textures {

/// Per-pixel coverage in [0, 1] of one vessel layer and the depth of the covering stroke.
struct VesselLayerImage {
  int width = 0;
  int height = 0;
  std::vector<float> coverage;
  std::vector<float> depth;
};

/// The trees of one layer as strokes in pixel coordinates of a width × height texture: each tree
/// starts at a random point with a direction from the layer spec, and its grammar is derived with
/// its own seed stream. Throws core::InputError if the grammar is malformed.
std::vector<core::TurtleSegment> grow_vessel_layer(const VesselLayerSpec& spec, int width,
                                                   int height, std::uint64_t seed);

/// Strokes bucketed by bands of rows, so a texture can be painted band by band while it is
/// composed, without full-size coverage buffers.
class VesselRasterizer {
 public:
  VesselRasterizer(std::vector<core::TurtleSegment> strokes, int width, int height);

  /// Paints rows [row_begin, row_end) into coverage/depth, which hold (row_end − row_begin) ×
  /// width values each and must be zeroed by the caller. Coverage is the maximum over strokes;
  /// on equal coverage the shallower stroke wins, so the result never depends on how the rows
  /// are split.
  void paint_rows(int row_begin, int row_end, float* coverage, float* depth) const;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  static constexpr int kBandRows = 16;
  std::vector<core::TurtleSegment> strokes_;
  std::vector<std::vector<int>> bands_;  ///< stroke indices overlapping each band, ascending
  int width_ = 0, height_ = 0;
};

/// Paints strokes as anti-aliased capsules whose width tapers from start_width to end_width
/// (pixels): coverage = max over strokes of clamp(w/2 − d + 0.5, 0, 1), scaled down for strokes
/// thinner than a pixel. Rows run in parallel; the result does not depend on the thread count.
VesselLayerImage paint_vessels(const std::vector<core::TurtleSegment>& strokes, int width,
                               int height, int threads = 0);

}  // namespace viscera::textures
