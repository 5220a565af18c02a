#include "studio/cli/command_output.h"

#include <cstdio>
#include <iostream>

namespace viscera::cli {

void print_json(const nlohmann::json& json) {
  std::cout << json.dump(2) << '\n';
}

void print_text(const std::string& text) {
  std::cout << text;
}

std::string human_bytes(std::uint64_t bytes) {
  static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  auto value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 4) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, kUnits[unit]);
  return text;
}

}  // namespace viscera::cli
