#pragma once
/// Axis-aligned boxes as closed triangle surfaces, for fixtures such as a floor or a table.

#include "core/mesh/surface_mesh.h"

namespace viscera::core {

/// A closed, outward-oriented box from `min` to `max` (m) whose faces are split into a grid of
/// squares of about `cell` m, two triangles each, with shared vertices along the edges.
/// Throws UsageError for an empty box or a non-positive cell.
SurfaceMesh make_box(const Vec3& min, const Vec3& max, double cell);

}  // namespace viscera::core
