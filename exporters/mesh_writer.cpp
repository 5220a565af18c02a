#include "exporters/mesh_writer.h"

#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <map>

#include "core/error.h"

namespace viscera::exporters {
namespace {

const std::map<std::string, std::string>& assimp_format_of_extension() {
  static const std::map<std::string, std::string> formats = {
      {".obj", "obj"}, {".stl", "stlb"}, {".ply", "plyb"}};
  return formats;
}

/// Builds an assimp scene that owns copies of the surfaces: a root node with one child node
/// and one mesh per surface, and one default material (assimp's exporters need one).
std::unique_ptr<aiScene> make_scene(const std::vector<NamedSurface>& surfaces) {
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("viscera");
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial*[1]{new aiMaterial()};
  scene->mNumMeshes = static_cast<unsigned>(surfaces.size());
  scene->mMeshes = new aiMesh*[surfaces.size()];
  scene->mRootNode->mNumChildren = scene->mNumMeshes;
  scene->mRootNode->mChildren = new aiNode*[surfaces.size()];
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    const core::SurfaceMesh& source = *surfaces[s].mesh;
    auto* mesh = new aiMesh();
    scene->mMeshes[s] = mesh;
    mesh->mName = surfaces[s].name;
    mesh->mMaterialIndex = 0;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = static_cast<unsigned>(source.vertices.size());
    mesh->mVertices = new aiVector3D[mesh->mNumVertices];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const auto& p = source.vertices[v];
      mesh->mVertices[v] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()),
                                      static_cast<ai_real>(p.z()));
    }
    if (!source.normals.empty()) {
      mesh->mNormals = new aiVector3D[mesh->mNumVertices];
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const auto& n = source.normals[v];
        mesh->mNormals[v] = aiVector3D(static_cast<ai_real>(n.x()), static_cast<ai_real>(n.y()),
                                       static_cast<ai_real>(n.z()));
      }
    }
    if (!source.uvs.empty()) {
      mesh->mNumUVComponents[0] = 2;  // BUILD_NOTES.md: keep 2 UV components
      mesh->mTextureCoords[0] = new aiVector3D[mesh->mNumVertices];
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const auto& uv = source.uvs[v];
        mesh->mTextureCoords[0][v] =
            aiVector3D(static_cast<ai_real>(uv.x()), static_cast<ai_real>(uv.y()), 0);
      }
    }
    mesh->mNumFaces = static_cast<unsigned>(source.triangles.size());
    mesh->mFaces = new aiFace[mesh->mNumFaces];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      mesh->mFaces[f].mNumIndices = 3;
      mesh->mFaces[f].mIndices = new unsigned[3];
      for (int c = 0; c < 3; ++c) mesh->mFaces[f].mIndices[c] = static_cast<unsigned>(source.triangles[f][c]);
    }
    auto* node = new aiNode(surfaces[s].name);
    node->mParent = scene->mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{static_cast<unsigned>(s)};
    scene->mRootNode->mChildren[s] = node;
  }
  return scene;
}

}  // namespace

std::vector<std::string> mesh_writer_extensions() {
  std::vector<std::string> list;
  for (const auto& [extension, format] : assimp_format_of_extension()) list.push_back(extension);
  return list;
}

void write_meshes(const std::vector<NamedSurface>& surfaces, const std::filesystem::path& path) {
  const std::string file = path.string();
  const auto& formats = assimp_format_of_extension();
  const auto format = formats.find(path.extension().string());
  if (format == formats.end()) {
    throw core::UsageError("cannot tell the mesh format of \"" + file + "\" from its extension");
  }
  if (surfaces.empty()) throw core::InputError("nothing to export", {file, "", ""});
  for (const auto& s : surfaces) {
    if (s.mesh == nullptr || s.mesh->triangles.empty()) {
      throw core::InputError("surface has no triangles", {file, "", s.name});
    }
    core::check_surface_mesh(*s.mesh, s.name);
  }
  const auto scene = make_scene(surfaces);
  // Write into a temporary folder beside the target, then rename each file into place: no
  // partial file on failure, and side files (an OBJ's .mtl) keep the names the main file uses.
  const std::filesystem::path parent = path.parent_path().empty() ? "." : path.parent_path();
  std::string staging_name = ".";  // appended step by step: GCC 12 warns falsely on a + b + c
  staging_name += path.filename().string();
  staging_name += ".partial";
  const std::filesystem::path staging = parent / staging_name;
  std::filesystem::remove_all(staging);
  std::filesystem::create_directories(staging);
  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), format->second, (staging / path.filename()).string()) != AI_SUCCESS) {
    std::filesystem::remove_all(staging);
    throw core::OutputError(std::string("cannot write mesh: ") + exporter.GetErrorString(), {file, "", ""});
  }
  for (const auto& entry : std::filesystem::directory_iterator(staging)) {
    std::filesystem::rename(entry.path(), parent / entry.path().filename());
  }
  std::filesystem::remove_all(staging);
}

}  // namespace viscera::exporters
