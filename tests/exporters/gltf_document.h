#pragma once
/// A glTF 2.0 file opened the way a viewer does, written for the tests from the specification
/// (§4 "Concepts", §4.4 "GLB file format"): the JSON, its binary buffers, and the floats or
/// integers of any accessor.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace viscera::testing {

class GltfDocument {
 public:
  /// Reads .gltf (buffers from data URIs or files beside it) or .glb (JSON and BIN chunks).
  /// Fails the test through gtest assertions on a malformed file.
  explicit GltfDocument(const std::filesystem::path& path);

  const nlohmann::json& json() const { return json_; }
  /// Components of accessor `index` as doubles (floats or unsigned integers), count × size.
  std::vector<double> accessor(int index) const;
  /// Bytes of the image `index` (from its buffer view or data URI).
  std::string image_bytes(int index) const;

 private:
  std::string view_bytes(int view) const;
  static std::string decode_data_uri(const std::string& uri);

  nlohmann::json json_;
  std::vector<std::string> buffers_;
};

}  // namespace viscera::testing
