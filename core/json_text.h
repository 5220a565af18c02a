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

/// True when `j` is an object whose "format" member is the string `format`. (nlohmann's
/// value("format", …) throws when the member has another type: the script_json and
/// procedure_json fuzz targets' finding.)
bool has_format(const nlohmann::json& j, const std::string& format);

/// `j`'s integer "version" member, or −1 when it is missing or not a whole number.
int format_version(const nlohmann::json& j);

}  // namespace viscera::core
