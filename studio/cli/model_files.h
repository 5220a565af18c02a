#pragma once
/// Reading and writing model documents and parsing point arguments for the `viscera model`
/// commands.

#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/modelling/model_document.h"

namespace viscera::cli {

/// The model in `path` (format viscera-model). Throws core::InputError / ValidationError
/// naming the file.
core::ModelDocument load_model(const std::string& path);

/// Writes `model` to `path` atomically (same model → same bytes).
void save_model(const core::ModelDocument& model, const std::string& path);

/// Parses "x,y,z" (m) given to `option`. Throws core::UsageError naming the option.
core::Vec3 parse_point(const std::string& text, const std::string& option);

/// Parses each of `texts` with parse_point.
std::vector<core::Vec3> parse_points(const std::vector<std::string>& texts,
                                     const std::string& option);

}  // namespace viscera::cli
