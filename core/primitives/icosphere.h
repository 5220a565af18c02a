#pragma once
/// Sphere surfaces by recursive subdivision of an icosahedron: nearly uniform triangles, which
/// the tetrahedral mesher and the Teschner area energy both prefer over latitude-longitude
/// spheres with their slivers at the poles.

#include "core/mesh/surface_mesh.h"

namespace viscera::core {

/// A closed, outward-oriented sphere of `radius` m centred at `center`, after `subdivisions`
/// 4-to-1 splits of the icosahedron (20·4^s triangles, 10·4^s + 2 vertices), with unit normals
/// and spherical UVs (u = longitude / 2π, v = colatitude / π). subdivisions in [0, 7].
/// Throws UsageError for a non-positive radius or subdivisions out of range.
SurfaceMesh make_icosphere(double radius, int subdivisions, const Vec3& center = Vec3::Zero());

/// Mean edge length in m of an icosphere of `radius` after `subdivisions` splits.
double icosphere_edge_length(double radius, int subdivisions);

/// The smallest subdivision count whose mean edge length is at most `edge_length`.
int icosphere_subdivisions_for_edge(double radius, double edge_length);

}  // namespace viscera::core
