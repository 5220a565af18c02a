#pragma once
/// Making a surface safe for strict file writers and readers before export: glTF requires unit
/// normals and finite accessors (assimp's glb2 writer fails on any NaN or inf, the Khronos
/// validator rejects non-unit normals), OBJ and PLY readers choke on "nan".

#include <cstddef>

#include "core/mesh/surface_mesh.h"

namespace viscera::exporters {

/// Sanitises `surface` in place and returns how many values it replaced:
/// - normals: missing ones are computed (area-weighted); a non-finite or zero normal is replaced
///   by the area-weighted normal of its triangles, or +z for a vertex without area; every normal
///   is normalised (renormalising alone is not counted);
/// - UVs: non-finite components become 0;
/// - vertex colours (attributes "albedo_r", "albedo_g", "albedo_b"): non-finite become 0, all
///   are clamped to [0, 1].
/// Throws core::InputError naming `what` and the vertex when a position is not finite: no value
/// can stand in for a lost position.
std::size_t sanitize_surface(core::SurfaceMesh& surface, const std::string& what);

}  // namespace viscera::exporters
