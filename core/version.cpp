#include "core/version.h"

#include <gmsh.h>
#include <vtkVersionMacros.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace viscera::core {

std::string viscera_version() {
  return VISCERA_VERSION;
}

std::map<std::string, std::string> tool_versions() {
  const auto join = [](int major, int minor, int patch) {
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
  };
  return {
      {"viscera", viscera_version()},
      {"gmsh", GMSH_API_VERSION},
      {"vtk", VTK_VERSION},
      {"eigen", join(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"nlohmann-json",
       join(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
  };
}

}  // namespace viscera::core
