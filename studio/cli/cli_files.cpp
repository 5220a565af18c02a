#include "studio/cli/cli_files.h"

#include <fstream>
#include <sstream>

#include "core/error.h"

namespace viscera::cli {

std::string read_file_bytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw core::InputError("is a folder, not a file", {path.string(), "", ""});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw core::InputError("cannot read the file", {path.string(), "", ""});
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw core::InputError("reading the file failed", {path.string(), "", ""});
  return bytes.str();
}

nlohmann::json read_json_file(const std::filesystem::path& path) {
  const std::string text = read_file_bytes(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw core::InputError("not JSON (byte " + std::to_string(e.byte) + ")",
                           {path.string(), "", ""});
  }
}

}  // namespace viscera::cli
