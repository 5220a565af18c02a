#include "simulator/session/simulation_check.h"

#include <cmath>
#include <span>
#include <sstream>

#include "core/mesh/tet_mesh.h"

namespace viscera::sim {

namespace {

std::string at_step(long long step, double time) {
  std::ostringstream text;
  text << "at step " << step << " (t = " << time << " s)";
  return text.str();
}

/// Tets of `tets` over `positions` whose signed volume has the opposite sign of their rest
/// volume over `rest`; tets touching a non-finite node are left out.
int count_inverted(const std::vector<core::Tetrahedron>& tets, std::span<const core::Vec3> rest,
                   std::span<const core::Vec3> positions) {
  int inverted = 0;
  for (const auto& t : tets) {
    bool inside = true;
    for (const int n : t)
      inside = inside && n >= 0 && static_cast<std::size_t>(n) < positions.size();
    if (!inside) continue;
    const auto& a = positions[t[0]];
    const auto& b = positions[t[1]];
    const auto& c = positions[t[2]];
    const auto& d = positions[t[3]];
    if (!(a.allFinite() && b.allFinite() && c.allFinite() && d.allFinite())) continue;
    const double now = core::signed_volume(a, b, c, d);
    const double before = core::signed_volume(rest[t[0]], rest[t[1]], rest[t[2]], rest[t[3]]);
    if (now * before < 0.0) ++inverted;
  }
  return inverted;
}

}  // namespace

std::optional<StateFault> find_state_fault(const World& world) {
  for (const BodyView& body : world.bodies()) {
    const std::span<const core::Vec3> x = body.positions();
    for (std::size_t n = 0; n < x.size(); ++n) {
      if (x[n].allFinite()) continue;
      StateFault fault;
      fault.body = body.name();
      fault.node = static_cast<long long>(n);
      fault.non_finite = true;
      // The body's own tets and rest positions (a cut may have changed them since the scenario).
      fault.inverted_tets = count_inverted(body.tets(), body.rest_positions(), x);
      return fault;
    }
  }
  return std::nullopt;
}

core::SimulationError simulation_error(const StateFault& fault, long long step, double time) {
  const std::string found = "the simulation became unstable " + at_step(step, time) + ": node " +
                            std::to_string(fault.node) + " of body \"" + fault.body +
                            "\" has a non-finite position";
  const std::string cause =
      fault.inverted_tets > 0
          ? std::to_string(fault.inverted_tets) +
                " inverted tets (the tissue was crushed through itself: the tool pressed harder "
                "or faster than the material and time step can hold)"
          : "non-finite state (the time step is too large for the material's stiffness and "
            "damping, so the integration diverged)";
  return core::SimulationError(found, fault.body, fault.node, step, cause);
}

core::SimulationError simulation_error(const std::string& what, const std::string& body,
                                       long long step, double time) {
  return core::SimulationError("the simulation failed " + at_step(step, time) + ": " + what, body,
                               -1, step, "an internal check of the physics failed");
}

}  // namespace viscera::sim
