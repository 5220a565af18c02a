#pragma once
/// Exporting a scenario (a whole package or some of its objects) for other tools: one entry
/// point that dispatches on the format to one file per format in exporters/.
///
// clang-format off
/// | format | OUT           | files written                                              | carries                                                        | for                 |
/// |--------|---------------|------------------------------------------------------------|----------------------------------------------------------------|---------------------|
/// | vtk    | X.vtm         | X.vtm, X/<id>_surface.vtp, X/<id>_body.vtu                  | every array of the package: normals, UVs, embedding, masses, fixed flags, tet labels (DESIGN §4) | ParaView |
/// | vtk    | X.vtp, X.vtu  | one file                                                   | the one selected object's surface or body                      | ParaView            |
/// | gltf   | X.gltf        | X.gltf, X.bin (PNG maps as data URIs)                      | a node and mesh per object: positions, unit normals, UVs, vertex colours; PBR material with the baked albedo as base-colour texture and the baked normal map | Unity, Blender, three.js |
/// | glb    | X.glb         | one binary glTF, maps in its buffer                        | same                                                           | same                |
/// | obj    | X.obj         | X.obj, X.mtl, X_<texture>_{albedo,normal,specular}.png     | groups per object, normals, UVs; map_Kd, bump/map_bump, map_Ks  | Blender, MeshLab    |
/// | stl    | X.stl         | binary STL                                                 | triangles of every object (one solid)                          | printing, CAD       |
/// | ply    | X.ply         | binary PLY (ASCII when an object has vertex colours)       | triangles, normals, UVs, vertex colours of every object        | MeshLab, CloudCompare |
/// | msh    | X.msh         | gmsh 4.1 ASCII                                             | every body's tets (a volume entity and physical group per object and label) with its boundary; surface-only objects as surfaces | gmsh, FEM codes |
/// | sofa   | X.scn         | X.scn, X_meshes/<id>_body.vtk, X_meshes/<id>_surface.obj (+ .mtl, maps) | a SOFA scene: TetrahedronFEMForceField or MeshSpringForceField, DiagonalMass, FixedProjectiveConstraint on the fixed nodes, a textured visual model mapped barycentrically, connections as springs (sofa_scene_exporter.h) | SOFA ≥ v24.06 |
// clang-format on
///
/// Before writing, every exported surface is sanitised (surface_sanitizer.h): non-finite or
/// zero normals are recomputed and normalised, non-finite UVs and colours replaced, so that strict
/// readers (assimp's glb2 writer, the Khronos validator) accept the file; non-finite positions are
/// refused. Positions stay in metres. The image format VTK .vti is written by `volume convert`
/// (image volumes); a package holds no image volume.
///
/// Every export is written into a temporary sibling folder and moved into place only when
/// complete (staged_output.h), so a failure leaves nothing behind.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::exporters {

/// The formats of `viscera export --format`.
enum class ExportFormat { Vtk, Gltf, Glb, Obj, Stl, Ply, Msh, Sofa };

/// "vtk", "gltf", … → format; throws core::UsageError naming the accepted ones otherwise.
ExportFormat export_format_from_string(const std::string& name);
std::string to_string(ExportFormat format);
/// Every format, in the order of the table above.
const std::vector<ExportFormat>& export_formats();

/// Package path → bytes of the baked texture maps a scenario's TextureSpec::maps name
/// ("textures/<id>_albedo.png"); see read_package_textures().
using TextureFiles = std::map<std::string, std::string>;

/// What to export.
struct ExportOptions {
  std::vector<std::string> objects;  ///< ids of the objects to export; empty = every object
};

/// What an export wrote.
struct ExportReport {
  std::vector<std::filesystem::path> files;  ///< every file written, main file first
  int objects = 0;
  std::size_t triangles = 0;
  std::size_t tets = 0;
  std::size_t sanitized_values = 0;  ///< normals, UVs and colours replaced (surface_sanitizer.h)
};

/// Writes `scenario` in `format` to `out` (see the table for the files around it). Maps named by
/// the objects' textures are taken from `textures`; a map that is named but missing there is an
/// error. Throws core::UsageError (unknown object id, a .vtp/.vtu target with several objects,
/// an extension that does not fit the format, nothing to export), core::InputError naming the
/// object and element of non-finite positions, and core::OutputError naming `out` when writing
/// fails; in every case nothing is left at or beside `out`.
ExportReport export_scenario(const core::Scenario& scenario, ExportFormat format,
                             const std::filesystem::path& out, const TextureFiles& textures = {},
                             const ExportOptions& options = {},
                             core::Progress& progress = core::Progress::none());

/// The texture maps named by `scenario` read from its package (a folder or a .vscz). Throws
/// core::InputError naming the package and the missing or unreadable map.
TextureFiles read_package_textures(const std::filesystem::path& package,
                                   const core::Scenario& scenario);

}  // namespace viscera::exporters
