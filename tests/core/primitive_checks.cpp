#include "tests/core/primitive_checks.h"

#include <cmath>
#include <map>

namespace viscera::testing {

::testing::AssertionResult is_watertight_and_outward(const core::SurfaceMesh& mesh) {
  if (!core::is_closed_and_consistently_oriented(mesh)) {
    return ::testing::AssertionFailure()
           << "not closed and consistently oriented (" << mesh.triangles.size() << " triangles)";
  }
  const double volume = core::enclosed_volume(mesh);
  if (!(volume > 0.0))
    return ::testing::AssertionFailure() << "enclosed volume " << volume << " is not positive";
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& f = mesh.triangles[t];
    const double area = 0.5 * (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                                  .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]])
                                  .norm();
    if (!(area > 0.0)) return ::testing::AssertionFailure() << "triangle " << t << " is degenerate";
  }
  return ::testing::AssertionSuccess();
}

double max_dihedral_turn(const core::SurfaceMesh& mesh) {
  std::map<std::pair<int, int>, core::Vec3> first_normal;
  double worst = 0.0;
  for (const auto& f : mesh.triangles) {
    const core::Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                             .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]])
                             .normalized();
    for (int e = 0; e < 3; ++e) {
      const auto key = std::minmax(f[e], f[(e + 1) % 3]);
      const auto [it, inserted] = first_normal.try_emplace({key.first, key.second}, n);
      if (!inserted) worst = std::max(worst, std::acos(std::clamp(it->second.dot(n), -1.0, 1.0)));
    }
  }
  return worst;
}

}  // namespace viscera::testing
