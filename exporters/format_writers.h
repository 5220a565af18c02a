#pragma once
/// The writer of each export format (scenario_exporter.h has the table). Each writes `main`
/// (a path inside a StagedOutput folder) and its side files beside it; `shown` is the final
/// target for error messages. Internal to exporters/.

#include <filesystem>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "exporters/export_object.h"

namespace viscera::exporters {

/// glTF 2.0 through assimp's gltf2 (JSON + .bin, maps as data URIs) or glb2 (one binary file).
void write_gltf(const std::vector<ExportObject>& objects, bool binary,
                const std::filesystem::path& main, const std::string& shown);
/// Wavefront OBJ with its MTL and the maps as PNG files beside it.
void write_obj(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown);
/// Binary STL of every object's triangles.
void write_stl(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown);
/// Binary little-endian PLY with normals, UVs and colours.
void write_ply(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown);
/// VTK XML: a .vtm multiblock with a folder of pieces, or a single .vtp/.vtu.
void write_vtk(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown);
/// gmsh 4.1 ASCII of the bodies (and of the surfaces of objects without one).
void write_msh(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown);
/// A SOFA scene with its meshes and maps in a folder beside it.
void write_sofa(const core::Scenario& scenario, const std::vector<ExportObject>& objects,
                const std::filesystem::path& main, const std::string& shown);

}  // namespace viscera::exporters
