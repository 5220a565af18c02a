#pragma once
/// Scene objects from KisMo's three primitive types (seed 001 §3.3: flat, pipe, ball) for the
/// studio's Create menu: the visual surface from core/primitives and a tetrahedral body from
/// core/meshing, so a created object is simulated like a template's organ. Lengths in m.

#include <string>

#include "core/math_types.h"
#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::studio {

enum class PrimitiveKind { Ball, Flat, Pipe };
/// "ball", "flat", "pipe".
std::string to_string(PrimitiveKind kind);

/// What to create. `size` is the ball's radius, the flat's edge length or the pipe's radius.
struct PrimitiveRequest {
  PrimitiveKind kind = PrimitiveKind::Ball;
  core::Vec3 center = core::Vec3::Zero();  ///< m
  double size = 0.02;                      ///< m
  double length = 0.08;                    ///< m, pipe only: centre-line length along x
  double cell_size = 0.006;                ///< m, target tet edge length of the body
};

/// `base`, or `base-2`, `base-3`, … — the first id no object of `scenario` has.
std::string unique_object_id(const core::Scenario& scenario, const std::string& base);

/// The object `id` for `request` with material `material_id` whose density sets the node
/// masses: surface (ball: icosphere level 3 through the ball shape; flat: 4 × 4 slab of
/// thickness size/10; pipe: three centre-line points, round caps), gmsh body, surface embedded
/// in the body. Throws core::UsageError for sizes ≤ 0, core::Error from meshing, CancelledError
/// through `progress`. Runs on any thread.
core::SceneObject build_primitive_object(const PrimitiveRequest& request, const std::string& id,
                                         const core::Material& material,
                                         core::Progress& progress = core::Progress::none());

}  // namespace viscera::studio
