#pragma once
/// A small hysteroscopy-like patient for the session tests: a spherical cavity (radius 15 mm)
/// inside a 7 mm wall, its outer surface held, the cavity wall marked by the vertex attribute
/// "cavity" = 1, and a diagnostic procedure whose targets are explicit positions: the "internal
/// os" low in the cavity, two "tubal orifices" left and right, withdrawal past the bottom.

#include <nlohmann/json.hpp>

#include "core/scenario/scenario.h"

namespace viscera::testing {

inline constexpr double kCavityRadius = 0.015;   ///< m
inline constexpr double kWallThickness = 0.007;  ///< m

/// The scenario (meshed once, then copied).
core::Scenario cavity_scenario();

/// A viscera-script (version 2) of timed waypoints {t, tip, look_at} for the cavity's wall.
nlohmann::json cavity_script(
    const std::vector<std::pair<double, std::pair<core::Vec3, core::Vec3>>>& waypoints);

/// The expert's diagnostic session on cavity_scenario(): straight in, a systematic panorama
/// from the centre, each orifice centred from 1 cm, straight out (about 12 s).
nlohmann::json expert_cavity_script();
/// The novice's: wanders, bumps the wall, looks at less of it, misses the left orifice (25 s).
nlohmann::json novice_cavity_script();

}  // namespace viscera::testing
