#pragma once
/// The text of data/textures/presets.json, compiled in so the product never reads the source tree.

namespace viscera::textures {

/// The built-in presets document.
const char* builtin_texture_presets_json();

}  // namespace viscera::textures
