#pragma once
/// Reading surface meshes made elsewhere: one entry point that dispatches on the extension.
///
/// | extension                       | reader  | carries                                   |
/// |---------------------------------|---------|-------------------------------------------|
/// | .obj .stl .ply .off .gltf .glb  | assimp  | triangles (polygons triangulated), normals, first UV set |
/// | .3ds .dae .fbx and other assimp | assimp  | same                                      |
///
/// Files state no unit, so the caller says which one they are in; the result is in metres.

#include <filesystem>
#include <string>

#include "core/mesh/surface_mesh.h"

namespace viscera::importers {

/// Length units a mesh file may be written in.
enum class LengthUnit { Metre, Centimetre, Millimetre };

/// Metres per unit.
double metres_per(LengthUnit unit);
/// "m", "cm", "mm" → unit; throws core::UsageError otherwise.
LengthUnit length_unit_from_string(const std::string& name);

/// Reads every mesh of the file into one SurfaceMesh in metres, node transforms applied,
/// coincident vertices joined. Throws core::InputError naming the file and the reason when it
/// cannot be read, holds no triangles, or has non-finite coordinates.
core::SurfaceMesh read_mesh(const std::filesystem::path& path, LengthUnit unit = LengthUnit::Metre);

}  // namespace viscera::importers
