#pragma once
/// Version of Viscera and of the libraries that shape its output, recorded in provenance.

#include <map>
#include <string>

namespace viscera::core {

/// "0.1.0" — the project version from CMake.
std::string viscera_version();

/// Name → version of Viscera and the libraries whose output ends up in packages
/// (gmsh, VTK, Eigen, nlohmann-json). Same build → same map, so packages stay reproducible.
std::map<std::string, std::string> tool_versions();

}  // namespace viscera::core
