#include "core/scenario/hydrometra_states.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace viscera::core {

PressureBracket bracket_pressure(std::span<const double> pressures, double pressure) {
  const int last = static_cast<int>(pressures.size()) - 1;
  if (!(pressure > pressures.front())) return {0, 0, 0.0};  // also NaN
  if (pressure >= pressures.back()) return {last, last, 0.0};
  // First pressure above `pressure`: its predecessor is at or below it.
  const auto above = std::upper_bound(pressures.begin(), pressures.end(), pressure);
  const int upper = static_cast<int>(above - pressures.begin());
  const int lower = upper - 1;
  const double p0 = pressures[static_cast<std::size_t>(lower)];
  const double p1 = pressures[static_cast<std::size_t>(upper)];
  return {lower, upper, (pressure - p0) / (p1 - p0)};
}

void interpolate_hydrometra(const HydrometraStates& states, double pressure, std::span<Vec3> out) {
  if (states.empty()) throw UsageError("hydrometra states are empty");
  if (out.size() != static_cast<std::size_t>(states.node_count))
    throw UsageError("hydrometra interpolation needs " + std::to_string(states.node_count) +
                     " nodes, got " + std::to_string(out.size()));
  const PressureBracket b = bracket_pressure(states.pressures, pressure);
  const std::span<const Vec3> lower = states.state(b.lower);
  if (b.t == 0.0) {
    std::copy(lower.begin(), lower.end(), out.begin());
    return;
  }
  // (1 − t) a + t b: exactly a at t = 0, exactly b at t = 1, the rounded mean at t = ½.
  const std::span<const Vec3> upper = states.state(b.upper);
  const double s = 1.0 - b.t;
  for (std::size_t n = 0; n < out.size(); ++n)
    out[n] = s * lower[n] + b.t * upper[n];
}

void check_hydrometra_states(const HydrometraStates& states, const std::string& what) {
  const auto fail = [&](const std::string& message) { throw InputError(message, {what, "", ""}); };
  if (states.empty()) return;
  if (states.node_count <= 0) fail("hydrometra states have no nodes");
  if (states.displacements.size() !=
      states.pressures.size() * static_cast<std::size_t>(states.node_count))
    fail("hydrometra states hold " + std::to_string(states.displacements.size()) +
         " displacements, not states × nodes");
  for (std::size_t k = 0; k < states.pressures.size(); ++k) {
    if (!std::isfinite(states.pressures[k])) fail("hydrometra pressure is not finite");
    if (k > 0 && !(states.pressures[k] > states.pressures[k - 1]))
      fail("hydrometra pressures do not increase at state " + std::to_string(k));
  }
  for (const Vec3& u : states.displacements)
    if (!u.allFinite()) fail("a hydrometra displacement is not finite");
}

}  // namespace viscera::core
