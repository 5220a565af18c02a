#pragma once
/// KisMo's "pipe" object type and flexible pipe modelling (seed 001 §3.3): a tube swept along a
/// Catmull-Rom centre line with chord-length knots (seed 002 §3.1) through control points, with
/// a radius profile interpolated the same way, cross-sections carried by rotation-minimising
/// frames so the tube never twists, and flat, round or no end caps. Positions and radii in m.

#include <string>
#include <vector>

#include "core/curves/cubic_curve.h"
#include "core/mesh/surface_mesh.h"

namespace viscera::core {

/// How a pipe end is closed.
enum class PipeCap { Flat, Round, Open };
std::string to_string(PipeCap cap);
/// Parses "flat", "round" or "open"; throws UsageError otherwise.
PipeCap pipe_cap_from_string(const std::string& name);

/// A single pipe: centre-line control points and a radius at each.
struct PipePrimitive {
  std::vector<Vec3> points;   ///< centre-line control points, m (≥ 2, neighbours distinct)
  std::vector<double> radii;  ///< m, one per point, positive
  PipeCap start_cap = PipeCap::Flat;
  PipeCap end_cap = PipeCap::Flat;
  int ring_segments = 32;  ///< vertices around each cross-section, ≥ 3
  double axial_spacing =
      0.0;  ///< m between cross-sections; 0 = the ring's edge length at the mean radius

  bool operator==(const PipePrimitive&) const = default;
};

/// Throws UsageError naming `what` when the fields disagree or a radius is not positive.
void check_pipe(const PipePrimitive& pipe, const std::string& what);

/// The centre line: Catmull-Rom with chord-length knots through the points.
CubicCurve pipe_centre_line(const PipePrimitive& pipe);
/// The radius profile over the centre line's knot parameter: Catmull-Rom through the radii with
/// the centre line's knots, kept at least a tenth of the smallest radius where it overshoots.
double pipe_radius_at(const PipePrimitive& pipe, const CubicCurve& centre_line, double t);

/// Extra sweep controls, used when pipes are joined into branching networks.
struct PipeSweepOptions {
  double start_extension = 0.0;  ///< m the tube continues straight back beyond its first point
};

/// The tube: rings at even arc length (plus the start extension), quads split into two
/// triangles outward, caps as concentric rings (flat) or a hemisphere (round). With both caps
/// closed the result is watertight and outward. UVs: u around (wrapping at the seam), v along
/// the length in [0, 1]; caps map to the end values of v. Vertex attribute "pipe_s" holds the
/// arc length in m of each ring along the centre line (caps: their end's value).
SurfaceMesh tessellate_pipe(const PipePrimitive& pipe, const PipeSweepOptions& options = {});

}  // namespace viscera::core
