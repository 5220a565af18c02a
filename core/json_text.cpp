#include "core/json_text.h"

#include <fstream>
#include <sstream>

#include "core/error.h"

namespace viscera::core {

nlohmann::json parse_json_text(const std::string& text, const std::string& file) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError("not valid JSON (syntax error at byte " + std::to_string(e.byte) + ")",
                     {file, "", ""});
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("not readable JSON: ") + e.what(), {file, "", ""});
  }
}

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open", {path, "", ""});
  std::stringstream text;
  text << in.rdbuf();
  return parse_json_text(text.str(), path);
}

bool has_format(const nlohmann::json& j, const std::string& format) {
  if (!j.is_object()) return false;
  const auto it = j.find("format");
  return it != j.end() && it->is_string() && it->get<std::string>() == format;
}

int format_version(const nlohmann::json& j) {
  if (!j.is_object()) return -1;
  const auto it = j.find("version");
  if (it == j.end() || !it->is_number_integer()) return -1;
  const auto v = it->get<long long>();
  return v >= 0 && v <= 1'000'000 ? static_cast<int>(v) : -1;
}

}  // namespace viscera::core
