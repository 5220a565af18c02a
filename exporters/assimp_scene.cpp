#include "exporters/assimp_scene.h"

#include <assimp/material.h>

#include <assimp/Exporter.hpp>
#include <cstring>

#include "core/error.h"

namespace viscera::exporters {
namespace {

aiVector3D to_ai(const core::Vec3& v) {
  return aiVector3D(static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()),
                    static_cast<ai_real>(v.z()));
}

aiMesh* make_mesh(const ExportObject& object, unsigned material) {
  const core::SurfaceMesh& surface = object.surface;
  auto* mesh = new aiMesh();
  mesh->mName = object.id();
  mesh->mMaterialIndex = material;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = static_cast<unsigned>(surface.vertices.size());
  mesh->mVertices = new aiVector3D[mesh->mNumVertices];
  mesh->mNormals = new aiVector3D[mesh->mNumVertices];
  for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
    mesh->mVertices[v] = to_ai(surface.vertices[v]);
    mesh->mNormals[v] = to_ai(surface.normals[v]);
  }
  if (!surface.uvs.empty()) {
    mesh->mNumUVComponents[0] = 2;  // BUILD_NOTES.md: keep 2 UV components
    mesh->mTextureCoords[0] = new aiVector3D[mesh->mNumVertices];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      mesh->mTextureCoords[0][v] = aiVector3D(static_cast<ai_real>(surface.uvs[v].x()),
                                              static_cast<ai_real>(surface.uvs[v].y()), 0);
    }
  }
  if (object.has_vertex_colors()) {
    const auto& r = surface.vertex_attributes.at("albedo_r");
    const auto& g = surface.vertex_attributes.at("albedo_g");
    const auto& b = surface.vertex_attributes.at("albedo_b");
    mesh->mColors[0] = new aiColor4D[mesh->mNumVertices];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      mesh->mColors[0][v] = aiColor4D(static_cast<ai_real>(r[v]), static_cast<ai_real>(g[v]),
                                      static_cast<ai_real>(b[v]), 1);
    }
  }
  mesh->mNumFaces = static_cast<unsigned>(surface.triangles.size());
  mesh->mFaces = new aiFace[mesh->mNumFaces];
  for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
    mesh->mFaces[f].mNumIndices = 3;
    mesh->mFaces[f].mIndices = new unsigned[3];
    for (int c = 0; c < 3; ++c)
      mesh->mFaces[f].mIndices[c] = static_cast<unsigned>(surface.triangles[f][c]);
  }
  return mesh;
}

aiTexture* embedded_png(const std::string& bytes, const std::string& name) {
  auto* texture = new aiTexture();
  texture->mWidth = static_cast<unsigned>(bytes.size());  // compressed: width is the byte count
  texture->mHeight = 0;
  std::strcpy(texture->achFormatHint, "png");
  texture->pcData = new aiTexel[(bytes.size() + sizeof(aiTexel) - 1) / sizeof(aiTexel)];
  std::memcpy(texture->pcData, bytes.data(), bytes.size());
  texture->mFilename = name;
  return texture;
}

}  // namespace

AssimpExportScene make_assimp_scene(const std::vector<ExportObject>& objects,
                                    TextureStorage storage, const std::string& stem) {
  AssimpExportScene result;
  result.scene = std::make_unique<aiScene>();
  aiScene& scene = *result.scene;
  const auto count = static_cast<unsigned>(objects.size());
  scene.mRootNode = new aiNode("viscera");
  scene.mNumMeshes = scene.mNumMaterials = count;
  scene.mMeshes = new aiMesh*[count];
  scene.mMaterials = new aiMaterial*[count];
  scene.mRootNode->mNumChildren = count;
  scene.mRootNode->mChildren = new aiNode*[count];
  std::vector<aiTexture*> textures;

  for (unsigned i = 0; i < count; ++i) {
    const ExportObject& object = objects[i];
    scene.mMeshes[i] = make_mesh(object, i);
    auto* material = new aiMaterial();
    scene.mMaterials[i] = material;
    const aiString name(object.material != nullptr ? object.material->id + "-" + object.id()
                                                   : object.id());
    material->AddProperty(&name, AI_MATKEY_NAME);
    const bool textured = storage != TextureStorage::None && object.maps.contains("albedo");
    const aiColor4D base = textured || object.has_vertex_colors()
                               ? aiColor4D(1, 1, 1, 1)
                               : aiColor4D(static_cast<ai_real>(kTissueBaseColor[0]),
                                           static_cast<ai_real>(kTissueBaseColor[1]),
                                           static_cast<ai_real>(kTissueBaseColor[2]), 1);
    material->AddProperty(&base, 1, AI_MATKEY_BASE_COLOR);
    material->AddProperty(&base, 1, AI_MATKEY_COLOR_DIFFUSE);
    const ai_real metallic = 0, roughness = static_cast<ai_real>(0.5);
    material->AddProperty(&metallic, 1, AI_MATKEY_METALLIC_FACTOR);
    material->AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
    if (storage == TextureStorage::None) continue;
    const std::pair<const char*, aiTextureType> slots[] = {{"albedo", aiTextureType_DIFFUSE},
                                                           {"albedo", aiTextureType_BASE_COLOR},
                                                           {"normal", aiTextureType_NORMALS},
                                                           {"specular", aiTextureType_SPECULAR}};
    std::map<std::string, std::string> references;
    for (const auto& [map, type] : slots) {
      const auto bytes = object.maps.find(map);
      if (bytes == object.maps.end()) continue;
      // glTF has no specular slot without an extension; its materials carry albedo and normals.
      if (storage == TextureStorage::Embedded && type == aiTextureType_SPECULAR) continue;
      auto& reference = references[map];
      if (reference.empty()) {
        const std::string file = stem + "_" + object.texture_id + "_" + map + ".png";
        if (storage == TextureStorage::Embedded) {
          reference = "*" + std::to_string(textures.size());
          textures.push_back(embedded_png(bytes->second, file));
        } else {
          reference = file;
          result.side_files.emplace_back(file, bytes->second);
        }
      }
      const aiString path(reference);
      material->AddProperty(&path, AI_MATKEY_TEXTURE(type, 0));
    }
  }
  for (unsigned i = 0; i < count; ++i) {
    auto* node = new aiNode(objects[i].id());
    node->mParent = scene.mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{i};
    scene.mRootNode->mChildren[i] = node;
  }
  if (!textures.empty()) {
    scene.mNumTextures = static_cast<unsigned>(textures.size());
    scene.mTextures = new aiTexture*[textures.size()];
    std::copy(textures.begin(), textures.end(), scene.mTextures);
  }
  return result;
}

void export_assimp_scene(const aiScene& scene, const std::string& format_id,
                         const std::filesystem::path& path, const std::string& shown) {
  Assimp::Exporter exporter;
  if (exporter.Export(&scene, format_id, path.string()) != AI_SUCCESS) {
    throw core::OutputError(
        std::string("assimp cannot write the file: ") + exporter.GetErrorString(), {shown, "", ""});
  }
}

}  // namespace viscera::exporters
