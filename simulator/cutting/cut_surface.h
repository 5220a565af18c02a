#pragma once
/// Cut surfaces in the deformed configuration: the surface swept by the active loop electrode
/// of a resectoscope (seed 000 §5.1: "A cut surface is defined according to the movement of
/// the activated loop electrode through the soft tissue"), a planar cut and the triangle closed
/// by the blades of laparoscopic scissors. All positions in m.

#include <vector>

#include "core/math_types.h"

namespace viscera::sim::cutting {

/// A triangulated cut surface. Triangles are oriented consistently (their normals give the
/// "+" side of the cut), none is degenerate.
struct CutSurface {
  std::vector<core::Vec3> vertices;
  std::vector<core::Triangle> triangles;
};

/// The wire loop of a resectoscope electrode in its own frame: an arc of `radius` m spanning
/// `arc_radians` (π: the usual U-shaped half loop, 2π: a closed ring) in the local x–y plane,
/// centred at the origin and hanging towards −y: point(θ) = radius·(sin θ, −cos θ, 0) for
/// θ ∈ [−arc/2, arc/2]. The instrument advances the loop along its local z axis.
struct LoopElectrode {
  double radius = 0.004;
  double arc_radians = 3.141592653589793;
  int segments = 16;  ///< straight pieces along the arc
};

/// One sample of the loop's sweep: the loop frame's origin and orientation in world (deformed)
/// coordinates.
struct LoopPose {
  core::Vec3 position = core::Vec3::Zero();
  core::Mat3 rotation = core::Mat3::Identity();  ///< columns: the loop's x, y, z axes in world
};

/// World positions of the loop's wire points (segments + 1) at `pose`.
std::vector<core::Vec3> loop_points(const LoopElectrode& loop, const LoopPose& pose);

/// The surface swept by the loop through the poses (in order): a ruled strip between the wire
/// at consecutive poses. Throws InputError for a radius that is not positive and finite, an arc
/// outside (0, 2π], fewer than 2 segments, fewer than two poses, a non-finite pose or rotation
/// that is not orthonormal, or a sweep that does not move the loop (all poses within 1e-3 of
/// the radius of each other).
CutSurface swept_loop_surface(const LoopElectrode& loop, const std::vector<LoopPose>& sweep);

/// The surface swept by a wire through its samples (in order): a ruled strip between the wire's
/// polyline at consecutive samples (an electrosurgical hook, or any electrode whose shape is not
/// the loop's). Throws InputError for fewer than two samples, a wire of fewer than two points,
/// samples of different point counts, a non-finite point, or samples that sweep no area.
CutSurface swept_wire_surface(const std::vector<std::vector<core::Vec3>>& samples);

/// A planar rectangle centred at `center` with unit `normal` ("+" side), half extents in m
/// along two in-plane axes (the first is `u_axis` made orthogonal to the normal), split into
/// divisions × divisions quads. Throws InputError for non-finite input, a zero normal, a u_axis
/// parallel to the normal, non-positive extents or divisions < 1.
CutSurface planar_cut_surface(const core::Vec3& center, const core::Vec3& normal,
                              const core::Vec3& u_axis, double half_width, double half_height,
                              int divisions = 8);

/// The triangle swept by closing scissor blades: hinge and the two blade tips when the jaws
/// opened, subdivided `divisions` times along the blades. Throws InputError for non-finite
/// points or blades that are collinear or of zero length.
CutSurface scissor_cut_surface(const core::Vec3& hinge, const core::Vec3& tip_a,
                               const core::Vec3& tip_b, int divisions = 8);

}  // namespace viscera::sim::cutting
