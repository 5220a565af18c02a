#pragma once
/// Turtle interpretation of L-system strings (Prusinkiewicz & Lindenmayer 1990, ch. 1.5 and
/// 1.10): the planar form paints vessels into textures, the spatial form gives vessel centre
/// lines (seed 001 §3.3 and §5.1.1).
///
/// | module      | action                                                                   |
/// |-------------|--------------------------------------------------------------------------|
/// | F(l[,w])    | draw a segment of length l (default step), optionally setting width w first; |
/// |             | drawn as `subdivisions` pieces that each turn by up to ± `wiggle` degrees    |
/// | f(l)        | move by l without drawing                                                 |
/// | +(a) -(a)   | turn left / right about the up vector by a degrees (default angle)        |
/// | &(a) ^(a)   | pitch down / up about the left vector                                     |
/// | \(a) /(a)   | roll left / right about the heading                                       |
/// | \|          | turn around (180° about up)                                              |
/// | [ ]         | push / pop the turtle state; a pushed branch is one order higher          |
/// | !(w) or !   | set the width to w, or multiply it by width_factor                        |
/// | '(d) or '   | set the depth below the surface to d, or add depth_step (0 = surface)     |
/// | other       | ignored (placeholders such as A, B)                                       |

#include <cstdint>
#include <functional>
#include <vector>

#include "core/lsystem/lsystem.h"
#include "core/math_types.h"

namespace viscera::core {

/// Start state and defaults of the turtle. Lengths and widths are in the caller's units
/// (pixels for textures, m for centre lines); angles in degrees.
struct TurtleOptions {
  Vec3 origin = Vec3::Zero();
  Vec3 heading = Vec3::UnitY();  ///< H
  Vec3 left = -Vec3::UnitX();    ///< L; U = H × L (for the defaults, +z: the planar case)
  double step = 1.0;             ///< length of F without a parameter
  double angle = 25.0;           ///< degrees, turns without a parameter
  double width = 1.0;            ///< initial width
  double width_factor = 0.7;     ///< ! without a parameter multiplies the width by this
  double taper = 0.0;            ///< relative width lost per unit length drawn (1/length)
  double depth_step = 0.1;       ///< ' without a parameter adds this to the depth
  double angle_jitter = 0.0;     ///< degrees; each turn varies uniformly by ± this
  int subdivisions = 1;          ///< each F is drawn as this many collinear-ish pieces
  double wiggle =
      0.0;  ///< degrees; before each piece the heading turns about up by ± this (tortuosity)
  std::uint64_t seed = 0;  ///< for angle_jitter, through the project's Rng
  /// Called after every move with the turtle's position and frame (heading, left, up), which it
  /// may change: e.g. to keep the turtle on an organ's surface with up along the surface normal.
  std::function<void(Vec3& position, Vec3& heading, Vec3& left, Vec3& up)> constrain;
};

/// One drawn segment. Width tapers linearly from start_width to end_width.
struct TurtleSegment {
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  double start_width = 0.0;
  double end_width = 0.0;
  double depth = 0.0;  ///< 0 at the surface, larger deeper
  int parent = -1;     ///< index of the segment drawn before on this branch, -1 at the root
  int order = 0;       ///< branch order: bracket nesting depth
};

/// Interprets `modules` with the turtle; segments come in drawing order, so a parent always
/// precedes its children. Throws InputError on unbalanced brackets.
std::vector<TurtleSegment> interpret_turtle(const LsystemString& modules,
                                            const TurtleOptions& options = {});

}  // namespace viscera::core
