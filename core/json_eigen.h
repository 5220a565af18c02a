#pragma once
/// JSON form of Eigen vectors: [x, y, z]. Eigen types live in namespace Eigen, where
/// argument-dependent lookup would not find converters of ours, so nlohmann's serializer is
/// specialised instead.

#include <nlohmann/json.hpp>

#include "core/math_types.h"

namespace nlohmann {

template <>
struct adl_serializer<viscera::core::Vec3> {
  static void to_json(json& j, const viscera::core::Vec3& v) {
    j = json::array({v.x(), v.y(), v.z()});
  }
  static void from_json(const json& j, viscera::core::Vec3& v) {
    if (!j.is_array() || j.size() != 3)
      throw json::type_error::create(302, "expected [x, y, z]", &j);
    v = viscera::core::Vec3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
  }
};

}  // namespace nlohmann
