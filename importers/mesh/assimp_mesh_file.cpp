#include "importers/mesh/assimp_mesh_file.h"

#include <assimp/BaseImporter.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/crash_guard.h"
#include "core/error.h"
#include "importers/mesh/glb_container.h"
#include "importers/mesh/mesh_integrity.h"
#include "importers/mesh/off_header.h"
#include "importers/mesh/ply_header.h"

namespace viscera::importers {
namespace {

bool ends_with_any_case(const std::string& text, const std::string& suffix) {
  if (suffix.size() > text.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[text.size() - suffix.size() + i])) !=
        std::tolower(static_cast<unsigned char>(suffix[i])))
      return false;
  }
  return true;
}

/// True when `reader` lists `file`'s extension among its own.
bool claims_extension(Assimp::BaseImporter& reader, const std::string& file) {
  std::set<std::string> extensions;
  reader.GetExtensionList(extensions);
  for (const std::string& extension : extensions) {
    if (ends_with_any_case(file, "." + extension)) return true;
  }
  return false;
}

/// Takes readers out of `importer` before it meets `file`, deleting them (UnregisterLoader only
/// takes a reader out of the list; nothing else deletes it):
/// - Open Game Engine Exchange, always: assimp 5.2's OpenGEX parser reads past its buffer on a
///   damaged file (the mesh_glb fuzz target's finding, AddressSanitizer in the guard's child);
///   it is no format for organs.
/// - when some reader claims `file`'s extension, every other reader: assimp hands a file its
///   extension's reader refuses to any reader whose signature check passes (the same finding: a
///   damaged .glb went on to OpenGEX), so a file is read as what its name says or refused. A file
///   whose extension no reader claims is still read by content.
void restrict_readers(Assimp::Importer& importer, const std::string& file) {
  std::vector<Assimp::BaseImporter*> kept, removed;
  for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
    Assimp::BaseImporter* reader = importer.GetImporter(i);
    (claims_extension(*reader, "x.ogex") ? removed : kept).push_back(reader);
  }
  const auto claiming = std::count_if(kept.begin(), kept.end(), [&](Assimp::BaseImporter* reader) {
    return claims_extension(*reader, file);
  });
  if (claiming > 0) {
    std::erase_if(kept, [&](Assimp::BaseImporter* reader) {
      if (claims_extension(*reader, file)) return false;
      removed.push_back(reader);
      return true;
    });
  }
  for (Assimp::BaseImporter* reader : removed) {
    if (importer.UnregisterLoader(reader) == AI_SUCCESS) delete reader;
  }
}

/// The index of the importer Assimp::Importer::ReadFile (5.2) will hand `file` to, by its own
/// rule: the one importer claiming the file's extension; among several, the first whose
/// signature check accepts the file; with none, the first of all importers that accepts it.
/// SIZE_MAX when none would.
std::size_t importer_reading(const Assimp::Importer& importer, const std::string& file) {
  std::vector<std::size_t> claiming;
  for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
    if (claims_extension(*importer.GetImporter(i), file)) claiming.push_back(i);
  }
  if (claiming.size() == 1) return claiming.front();
  for (const std::size_t i : claiming) {
    if (importer.GetImporter(i)->CanRead(file, importer.GetIOHandler(), true)) return i;
  }
  for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
    if (importer.GetImporter(i)->CanRead(file, importer.GetIOHandler(), true)) return i;
  }
  return static_cast<std::size_t>(-1);
}

}  // namespace

core::SurfaceMesh read_assimp_surface(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::is_regular_file(path)) {
    throw core::InputError("no such file", {file, "", ""});
  }
  if (is_glb_container(path)) check_glb_container(path);  // assimp trusts chunk lengths
  Assimp::Importer importer;
  restrict_readers(importer, file);
  // Assimp's OFF and PLY readers trust the counts a header declares (off_header.h,
  // ply_header.h): the header is checked first when one of them is about to read the file.
  const std::size_t reader = importer_reading(importer, file);
  if (reader != static_cast<std::size_t>(-1)) {
    if (reader == importer.GetImporterIndex("off")) check_off_counts(path);
    if (reader == importer.GetImporterIndex("ply")) check_ply_header(path);
  }
  // Triangulate polygons, bake node transforms, check indices, and drop points and lines.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  unsigned flags = aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType |
                   aiProcess_ValidateDataStructure;
  // STL gives each triangle corner its face normal, which keeps corners apart when vertices
  // are joined; drop those normals and compute smooth ones from the welded mesh instead.
  const bool facet_normals_only = path.extension() == ".stl" || path.extension() == ".STL";
  if (facet_normals_only) flags |= aiProcess_DropNormals;
  // Assimp can crash on a damaged file (mesh_ply fuzz target: a SEGV in its post-processing): the
  // read runs first in a forked child, as the VTK readers' do (core/crash_guard.h).
  if (!core::survives_in_child([&] {
        Assimp::Importer trial;
        restrict_readers(trial, file);
        trial.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                 aiPrimitiveType_POINT | aiPrimitiveType_LINE);
        trial.ReadFile(file, flags);
      }))
    throw core::InputError(
        "the file is damaged: assimp crashes, hangs or exhausts its memory on it", {file, "", ""});
  const aiScene* scene = importer.ReadFile(file, flags);
  if (scene == nullptr) {
    throw core::InputError(std::string("cannot read mesh: ") + importer.GetErrorString(),
                           {file, "", ""});
  }
  core::SurfaceMesh mesh;
  bool all_have_normals = true, all_have_uvs = true;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    if ((part->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    all_have_normals = all_have_normals && part->HasNormals();
    all_have_uvs = all_have_uvs && part->HasTextureCoords(0);
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    if ((part->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    const int offset = static_cast<int>(mesh.vertices.size());
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      const aiVector3D& p = part->mVertices[v];
      mesh.vertices.emplace_back(static_cast<double>(p.x), static_cast<double>(p.y),
                                 static_cast<double>(p.z));
      if (all_have_normals) {
        const aiVector3D& n = part->mNormals[v];
        mesh.normals.emplace_back(n.x, n.y, n.z);
      }
      if (all_have_uvs) {
        const aiVector3D& uv = part->mTextureCoords[0][v];
        mesh.uvs.emplace_back(uv.x, uv.y);
      }
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.push_back({offset + static_cast<int>(face.mIndices[0]),
                                offset + static_cast<int>(face.mIndices[1]),
                                offset + static_cast<int>(face.mIndices[2])});
    }
  }
  if (mesh.triangles.empty()) throw core::InputError("file holds no triangles", {file, "", ""});
  // Corners are joined here, exactly: assimp's aiProcess_JoinIdenticalVertices uses a tolerance
  // of the bounding box that merges distinct corners of small meshes into pinches.
  join_identical_vertices(mesh);
  if (facet_normals_only) core::compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace viscera::importers
