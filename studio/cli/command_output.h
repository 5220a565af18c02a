#pragma once
/// How commands print results: human text by default, one JSON document with --json.

#include <nlohmann/json.hpp>
#include <string>

namespace viscera::cli {

/// Prints `json` (pretty, 2 spaces) to stdout with a trailing newline.
void print_json(const nlohmann::json& json);

/// Prints `text` to stdout as is.
void print_text(const std::string& text);

/// Formats a byte count as "12.3 MiB".
std::string human_bytes(std::uint64_t bytes);

}  // namespace viscera::cli
