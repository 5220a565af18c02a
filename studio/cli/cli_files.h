#pragma once
/// Reading whole input files for the commands; outputs go through
/// textures::write_file_atomically so a failure leaves nothing behind.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace viscera::cli {

/// The bytes of `path`. Throws core::InputError naming the file when it cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

/// The JSON document in `path`. Throws core::InputError naming the file (and the byte where
/// parsing stopped) when it cannot be read or is not JSON.
nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace viscera::cli
