#pragma once
/// The text of data/materials/tissues.json, compiled in by CMake (core/CMakeLists.txt).

namespace viscera::core {

const char* shipped_materials_json();

}  // namespace viscera::core
