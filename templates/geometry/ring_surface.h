#pragma once
/// Closed surfaces swept from a sequence of rings between two poles: each ring a closed loop of
/// its own number of points, neighbouring rings stitched into a strip of triangles by the
/// shortest-diagonal rule (Fuchs, Kedem & Uselton 1977, greedy form), each pole fanned to its
/// ring. A meridian that goes down the inside of an organ and back up its outside gives one
/// genus-0 surface holding both — a uterus wall with its cavity and cervical canal. The rings
/// may have different point counts, so each part of an organ gets the edge length it needs.

#include <vector>

#include "core/mesh/surface_mesh.h"

namespace viscera::templates {

/// A closed loop of points in m, counter-clockwise seen from the first pole's side when the
/// meridian runs from the first pole to the last; all rings start at the same angle.
using Ring = std::vector<core::Vec3>;

/// The surface from `first_pole` through `rings` to `last_pole`. Triangles are oriented so that
/// the enclosed volume is positive. Vertices: first pole, the rings in order, last pole.
/// Throws core::UsageError when there are fewer than one ring or a ring has fewer than 3 points.
core::SurfaceMesh ring_surface(const core::Vec3& first_pole, const std::vector<Ring>& rings,
                               const core::Vec3& last_pole);

/// Points on the ellipse centre + a·cos t·x_axis + b·sin t·y_axis, `count` of them evenly spaced
/// by arc length, starting at t = 0. a, b in m.
Ring ellipse_ring(const core::Vec3& centre, const core::Vec3& x_axis, const core::Vec3& y_axis,
                  double a, double b, int count);

/// Perimeter in m of an ellipse with semi-axes a and b (Ramanujan's second approximation).
double ellipse_perimeter(double a, double b);

}  // namespace viscera::templates
