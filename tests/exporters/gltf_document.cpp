#include "tests/exporters/gltf_document.h"

#include <gtest/gtest.h>

#include <cstring>

#include "tests/exporters/export_fixtures.h"

namespace viscera::testing {
namespace {

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;
}

int components_of(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  if (type == "MAT4") return 16;
  ADD_FAILURE() << "accessor type " << type;
  return 1;
}

int component_bytes(int type) {
  switch (type) {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
  }
  ADD_FAILURE() << "component type " << type;
  return 4;
}

}  // namespace

GltfDocument::GltfDocument(const std::filesystem::path& path) {
  const std::string bytes = file_bytes(path);
  if (path.extension() == ".glb") {
    EXPECT_GE(bytes.size(), 20u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    EXPECT_EQ(le32(bytes, 4), 2u) << "GLB version";
    EXPECT_EQ(le32(bytes, 8), bytes.size()) << "GLB length";
    std::size_t at = 12;
    while (at + 8 <= bytes.size()) {
      const std::uint32_t length = le32(bytes, at), type = le32(bytes, at + 4);
      EXPECT_EQ(length % 4, 0u) << "chunks are 4-byte aligned";
      const std::string chunk = bytes.substr(at + 8, length);
      if (type == 0x4E4F534Au) json_ = nlohmann::json::parse(chunk);  // "JSON"
      if (type == 0x004E4942u) buffers_.push_back(chunk);             // "BIN\0"
      at += 8 + length;
    }
    EXPECT_EQ(at, bytes.size());
  } else {
    json_ = nlohmann::json::parse(bytes);
    for (const auto& buffer : json_.value("buffers", nlohmann::json::array())) {
      const std::string uri = buffer.at("uri").get<std::string>();
      buffers_.push_back(uri.rfind("data:", 0) == 0 ? decode_data_uri(uri)
                                                    : file_bytes(path.parent_path() / uri));
      EXPECT_GE(buffers_.back().size(), buffer.at("byteLength").get<std::size_t>());
    }
  }
  EXPECT_EQ(json_.at("asset").at("version"), "2.0");
}

std::string GltfDocument::view_bytes(int view) const {
  const auto& v = json_.at("bufferViews").at(static_cast<std::size_t>(view));
  const std::string& buffer = buffers_.at(v.at("buffer").get<std::size_t>());
  return buffer.substr(v.value("byteOffset", std::size_t{0}),
                       v.at("byteLength").get<std::size_t>());
}

std::vector<double> GltfDocument::accessor(int index) const {
  const auto& a = json_.at("accessors").at(static_cast<std::size_t>(index));
  const int components = components_of(a.at("type").get<std::string>());
  const int type = a.at("componentType").get<int>();
  const int size = component_bytes(type);
  const auto count = a.at("count").get<std::size_t>();
  const int view = a.at("bufferView").get<int>();
  const std::string bytes = view_bytes(view);
  const auto& v = json_.at("bufferViews").at(static_cast<std::size_t>(view));
  const std::size_t stride = v.value("byteStride", static_cast<std::size_t>(components * size));
  const std::size_t offset = a.value("byteOffset", std::size_t{0});
  std::vector<double> values;
  values.reserve(count * static_cast<std::size_t>(components));
  for (std::size_t i = 0; i < count; ++i) {
    for (int c = 0; c < components; ++c) {
      const std::size_t at = offset + i * stride + static_cast<std::size_t>(c * size);
      EXPECT_LE(at + static_cast<std::size_t>(size), bytes.size());
      if (type == 5126) {
        float f;
        std::memcpy(&f, bytes.data() + at, 4);
        values.push_back(static_cast<double>(f));
      } else {
        std::uint32_t u = 0;
        std::memcpy(&u, bytes.data() + at, static_cast<std::size_t>(size));
        values.push_back(static_cast<double>(u));
      }
    }
  }
  return values;
}

std::string GltfDocument::image_bytes(int index) const {
  const auto& image = json_.at("images").at(static_cast<std::size_t>(index));
  if (image.contains("bufferView")) return view_bytes(image.at("bufferView").get<int>());
  return decode_data_uri(image.at("uri").get<std::string>());
}

std::string GltfDocument::decode_data_uri(const std::string& uri) {
  const auto comma = uri.find(',');
  EXPECT_NE(uri.find(";base64"), std::string::npos) << uri.substr(0, 40);
  static const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::uint32_t bits = 0;
  int count = 0;
  for (std::size_t i = comma + 1; i < uri.size() && uri[i] != '='; ++i) {
    const auto value = alphabet.find(uri[i]);
    if (value == std::string::npos) continue;
    bits = (bits << 6) | static_cast<std::uint32_t>(value);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<char>((bits >> count) & 0xffu));
    }
  }
  return out;
}

}  // namespace viscera::testing
