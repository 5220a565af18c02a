#include "simulator/session/instrument_input.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/json_eigen.h"

namespace viscera::sim {

ScriptedTrajectory ScriptedTrajectory::from_json(const nlohmann::json& json, const std::string& file) {
  const auto fail = [&file](const std::string& pointer, const std::string& message) {
    throw core::InputError(message, {file, pointer, ""});
  };
  if (!json.is_object() || json.value("format", std::string()) != "viscera-script") {
    fail("/format", "not a Viscera script (format must be \"viscera-script\")");
  }
  if (json.value("version", 0) != 1) fail("/version", "script version must be 1");
  ScriptedTrajectory script;
  script.body_ = json.value("body", std::string());
  if (script.body_.empty()) fail("/body", "names no body for the instrument to touch");
  script.stiffness_ = json.value("stiffness", 200.0);
  if (!(script.stiffness_ > 0.0)) fail("/stiffness", "stiffness must be positive (N/m)");
  script.perforation_depth_ = json.value("perforation_depth", 0.0);
  if (!(script.perforation_depth_ >= 0.0)) fail("/perforation_depth", "perforation depth must be ≥ 0 (m)");
  script.force_warning_ = json.value("force_warning", 0.0);
  if (!(script.force_warning_ >= 0.0)) fail("/force_warning", "force warning level must be ≥ 0 (N)");
  const auto waypoints = json.find("waypoints");
  if (waypoints == json.end() || !waypoints->is_array() || waypoints->empty()) fail("/waypoints", "needs at least one waypoint");
  for (std::size_t i = 0; i < waypoints->size(); ++i) {
    const std::string pointer = "/waypoints/" + std::to_string(i);
    try {
      const double t = (*waypoints)[i].at("t").get<double>();
      const core::Vec3 tip = (*waypoints)[i].at("tip").get<core::Vec3>();
      if ((i == 0 && t != 0.0) || (i > 0 && !(t > script.times_.back())) || !tip.allFinite()) {
        fail(pointer, "waypoint times must start at 0 and increase, tips must be finite");
      }
      script.times_.push_back(t);
      script.tips_.push_back(tip);
    } catch (const nlohmann::json::exception& e) {
      fail(pointer, std::string("waypoint needs \"t\" (s) and \"tip\" [x, y, z] (m): ") + e.what());
    }
  }
  return script;
}

ScriptedTrajectory ScriptedTrajectory::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw core::InputError("cannot open script", {path, "", ""});
  std::stringstream text;
  text << in.rdbuf();
  try {
    return from_json(nlohmann::json::parse(text.str()), path);
  } catch (const nlohmann::json::parse_error& e) {
    throw core::InputError("not valid JSON (syntax error at byte " + std::to_string(e.byte) + ")", {path, "", ""});
  }
}

core::Vec3 ScriptedTrajectory::tip(long long /*step*/, double time) const {
  if (time <= times_.front()) return tips_.front();
  if (time >= times_.back()) return tips_.back();
  const auto next = static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), time) - times_.begin());
  const double f = (time - times_[next - 1]) / (times_[next] - times_[next - 1]);
  return (1.0 - f) * tips_[next - 1] + f * tips_[next];
}

core::Vec3 RecordedInput::tip(long long step, double /*time*/) const {
  if (tips_.empty()) return core::Vec3::Zero();
  return tips_[static_cast<std::size_t>(std::clamp<long long>(step, 0, static_cast<long long>(tips_.size()) - 1))];
}

}  // namespace viscera::sim
