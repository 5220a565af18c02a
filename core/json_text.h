#pragma once
/// JSON documents a user hands the tools (manifests, scripts, traces, reports), parsed with every
/// failure of nlohmann::json — a syntax error, a number too large for a double (found by the
/// script_json fuzz target) — turned into one core::InputError naming the file.

#include <nlohmann/json.hpp>
#include <string>

namespace viscera::core {

/// Parses `text`; throws InputError naming `file` and the byte of a syntax error.
nlohmann::json parse_json_text(const std::string& text, const std::string& file);

/// Reads and parses the file at `path`; throws InputError when it cannot be opened or parsed.
nlohmann::json read_json_file(const std::string& path);

}  // namespace viscera::core
