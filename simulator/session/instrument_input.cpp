#include "simulator/session/instrument_input.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/json_eigen.h"
#include "core/json_numbers.h"
#include "core/json_text.h"
#include "core/scenario/landmark_frame.h"

namespace viscera::sim {

nlohmann::json resolve_script_landmarks(const nlohmann::json& script,
                                        const std::vector<core::Landmark>& landmarks,
                                        const std::string& file) {
  nlohmann::json out = script;
  if (!out.is_object() || !out.contains("waypoints") || !out["waypoints"].is_array()) return out;
  const auto find = [&](const std::string& id, const std::string& pointer) {
    const auto it = std::find_if(landmarks.begin(), landmarks.end(),
                                 [&id](const core::Landmark& l) { return l.id == id; });
    if (it == landmarks.end()) {
      std::string known;
      for (const auto& l : landmarks)
        known += (known.empty() ? "" : ", ") + l.id;
      throw core::InputError("the scenario has no landmark \"" + id +
                                 "\" (it has: " + (known.empty() ? "none" : known) + ")",
                             {file, pointer, ""});
    }
    return *it;
  };
  const auto frame_offset = [](const core::Landmark& mark, const nlohmann::json& abc) {
    return core::landmark_frame(mark.normal).offset(abc.get<core::Vec3>());
  };
  // The places of a waypoint, or of the second port's tool in it (`holder`, at `base`).
  const auto resolve = [&](nlohmann::json& holder, const std::string& base) {
    // Directions in a landmark's frame: {"landmark": id, "frame": [a, b, c]}.
    for (const char* key : {"axis", "up"}) {
      nlohmann::json& direction = holder[key];
      if (!direction.is_object()) {
        if (direction.is_null()) holder.erase(key);
        continue;
      }
      const std::string pointer = base + "/" + key;
      try {
        const core::Landmark mark = find(direction.at("landmark").get<std::string>(), pointer);
        direction = frame_offset(mark, direction.at("frame"));
      } catch (const nlohmann::json::exception& e) {
        throw core::InputError(std::string("a direction in a landmark's frame needs "
                                           "\"landmark\" and \"frame\" [a, b, c]: ") +
                                   e.what(),
                               {file, pointer, ""});
      }
    }
    for (const char* key : {"tip", "look_at"}) {
      nlohmann::json& place = holder[key];
      const std::string pointer = base + "/" + key;
      if (!place.is_object()) {
        if (place.is_null()) holder.erase(key);
        continue;
      }
      try {
        const core::Landmark from = find(place.at("landmark").get<std::string>(), pointer);
        core::Vec3 p = from.position;
        if (place.contains("towards")) {
          const core::Landmark to = find(place["towards"].get<std::string>(), pointer);
          p += place.value("fraction", 0.0) * (to.position - from.position);
        }
        p += place.value("along_normal", 0.0) * from.normal;
        if (place.contains("offset")) p += place["offset"].get<core::Vec3>();
        if (place.contains("frame")) p += frame_offset(from, place["frame"]);
        // A tip that follows the tissue is anchored where its landmark lies.
        if (key == std::string("tip") && place.value("follow", false)) {
          holder["tip_anchor"] = from.position;
          if (!from.object.empty()) holder["tip_anchor_body"] = from.object;
        }
        place = p;
      } catch (const nlohmann::json::exception& e) {
        throw core::InputError(std::string("a landmark place needs \"landmark\" and optional "
                                           "\"towards\", \"fraction\", \"along_normal\", "
                                           "\"offset\" [x, y, z], \"frame\" [a, b, c], "
                                           "\"follow\" true|false: ") +
                                   e.what(),
                               {file, pointer, ""});
      }
    }
  };
  for (std::size_t i = 0; i < out["waypoints"].size(); ++i) {
    nlohmann::json& waypoint = out["waypoints"][i];
    const std::string pointer = "/waypoints/" + std::to_string(i);
    resolve(waypoint, pointer);
    if (waypoint.contains("left") && waypoint["left"].is_object())
      resolve(waypoint["left"], pointer + "/left");
    if (waypoint.contains("camera") && waypoint["camera"].is_object())
      resolve(waypoint["camera"], pointer + "/camera");
  }
  return out;
}

namespace {

/// A switch of a waypoint, `key`: 0 or 1, held from this waypoint until a later one changes it.
void read_switch(const nlohmann::json& w, const char* key, const std::string& file,
                 const std::string& pointer, bool& out) {
  if (!w.contains(key)) return;
  const auto& value = w[key];
  if (!core::whole_number_fits<int>(value) || (value != 0 && value != 1))
    throw core::InputError(std::string(key) + " must be 0 or 1", {file, pointer + "/" + key, ""});
  out = value == 1;
}

/// The laparoscopic tool of a waypoint's port, held the same way.
void read_tool(const nlohmann::json& w, const std::string& file, const std::string& pointer,
               LaparoscopicTool& out) {
  if (!w.contains("tool")) return;
  const auto& name = w["tool"];
  const auto tool = name.is_string() ? tool_from_name(name.get<std::string>()) : std::nullopt;
  if (!tool)
    throw core::InputError(
        "tool must be one of \"none\", \"grasper\", \"clip-applier\", "
        "\"scissors\", \"bipolar\", \"suction\", \"hook\"",
        {file, pointer + "/tool", ""});
  out = *tool;
}

/// The second port's tool at a waypoint, `left` at `pointer`: {"tip", "axis", "up", "tool",
/// "close", "coagulate", "activate", "irrigate"} held as the working port's, or
/// {"withdraw": true} to take it out. A tool put in needs a tip.
void read_second_port(const nlohmann::json& left, const std::string& file,
                      const std::string& pointer, SecondPort& port) {
  if (!left.is_object())
    throw core::InputError("the second port's tool must be an object", {file, pointer, ""});
  if (left.value("withdraw", false)) {
    port = SecondPort{};
    return;
  }
  if (left.contains("tip_anchor"))
    throw core::InputError("the second port's tip does not follow the tissue (no \"follow\")",
                           {file, pointer + "/tip", ""});
  if (!port.inserted && !left.contains("tip"))
    throw core::InputError("a tool put into the second port needs a \"tip\" [x, y, z] (m)",
                           {file, pointer, ""});
  try {
    if (left.contains("tip")) port.tip = left["tip"].get<core::Vec3>();
    if (left.contains("axis")) port.axis = left["axis"].get<core::Vec3>();
    if (left.contains("up")) port.up = left["up"].get<core::Vec3>();
  } catch (const nlohmann::json::exception& e) {
    throw core::InputError(
        std::string("the second port's tip, axis and up are [x, y, z]: ") + e.what(),
        {file, pointer, ""});
  }
  if (!port.tip.allFinite() || !port.axis.allFinite() || port.axis.norm() == 0.0 ||
      !port.up.allFinite())
    throw core::InputError("the second port's tip and axis must be finite, the axis non-zero",
                           {file, pointer, ""});
  port.inserted = true;
  read_tool(left, file, pointer, port.tool);
  read_switch(left, "close", file, pointer, port.jaws_closed);
  read_switch(left, "coagulate", file, pointer, port.coagulation);
  read_switch(left, "activate", file, pointer, port.electrode);
  read_switch(left, "irrigate", file, pointer, port.irrigating);
  port.axis.normalize();
  port.up -= port.up.dot(port.axis) * port.axis;
  if (port.up.norm() < 1e-12) port.up = port.axis.unitOrthogonal();
  port.up.normalize();
}

/// The laparoscope held as a camera at a waypoint, `block` at `pointer`: {"tip", "look_at", "up"}
/// (the angled optics aimed at a point, the shaft below the view so that "up" — default the
/// previous camera's, else +z — is the picture's up, as an assistant keeps the horizon level)
/// or {"tip", "axis", "up"}, held as the working port's pose, or {"release": true} to give the
/// optics back to the working port.
void read_camera(const nlohmann::json& block, const std::string& file, const std::string& pointer,
                 double optics_angle, LaparoscopeCamera& camera) {
  if (!block.is_object())
    throw core::InputError("the camera must be an object", {file, pointer, ""});
  if (block.value("release", false)) {
    camera = LaparoscopeCamera{};
    return;
  }
  if (!camera.held && !block.contains("tip"))
    throw core::InputError("a laparoscope taken up as the camera needs a \"tip\" [x, y, z] (m)",
                           {file, pointer, ""});
  try {
    if (block.contains("tip")) camera.tip = block["tip"].get<core::Vec3>();
    if (block.contains("look_at")) {
      const core::Vec3 picture_up = block.contains("up") ? block["up"].get<core::Vec3>()
                                    : camera.held        ? camera.up
                                                         : core::Vec3::UnitZ();
      const InstrumentState aimed =
          look_at(camera.tip, block["look_at"].get<core::Vec3>(), -picture_up, optics_angle);
      camera.axis = aimed.axis;
      camera.up = aimed.up;
    } else {
      if (block.contains("axis")) camera.axis = block["axis"].get<core::Vec3>();
      if (block.contains("up")) camera.up = block["up"].get<core::Vec3>();
    }
  } catch (const nlohmann::json::exception& e) {
    throw core::InputError(
        std::string("the camera's tip, axis, up and look_at are [x, y, z]: ") + e.what(),
        {file, pointer, ""});
  }
  if (!camera.tip.allFinite() || !camera.axis.allFinite() || camera.axis.norm() == 0.0 ||
      !camera.up.allFinite())
    throw core::InputError("the camera's tip and axis must be finite, the axis non-zero",
                           {file, pointer, ""});
  camera.held = true;
  camera.axis.normalize();
  camera.up -= camera.up.dot(camera.axis) * camera.axis;
  if (camera.up.norm() < 1e-12) camera.up = camera.axis.unitOrthogonal();
  camera.up.normalize();
}

}  // namespace

ScriptedTrajectory ScriptedTrajectory::from_json(const nlohmann::json& json,
                                                 const std::string& file, double optics_angle) {
  const auto fail = [&file](const std::string& pointer, const std::string& message) {
    throw core::InputError(message, {file, pointer, ""});
  };
  if (!core::has_format(json, "viscera-script")) {
    fail("/format", "not a Viscera script (format must be \"viscera-script\")");
  }
  const int version = core::format_version(json);
  if (version != 1 && version != 2) fail("/version", "script version must be 1 or 2");
  ScriptedTrajectory script;
  try {
    script.body_ = json.value("body", std::string());
    script.stiffness_ = json.value("stiffness", 200.0);
    script.perforation_depth_ = json.value("perforation_depth", 0.0);
    script.force_warning_ = json.value("force_warning", 0.0);
    optics_angle = json.value("optics_angle", optics_angle);
  } catch (const nlohmann::json::exception& e) {
    fail("", std::string("a top-level member has the wrong type: ") + e.what());
  }
  if (version == 1 && script.body_.empty())
    fail("/body", "names no body for the instrument to touch");
  if (!(script.stiffness_ > 0.0)) fail("/stiffness", "stiffness must be positive (N/m)");
  if (!(script.perforation_depth_ >= 0.0))
    fail("/perforation_depth", "perforation depth must be ≥ 0 (m)");
  if (!(script.force_warning_ >= 0.0))
    fail("/force_warning", "force warning level must be ≥ 0 (N)");
  const auto waypoints = json.find("waypoints");
  if (waypoints == json.end() || !waypoints->is_array() || waypoints->empty())
    fail("/waypoints", "needs at least one waypoint");
  InstrumentState previous;
  for (std::size_t i = 0; i < waypoints->size(); ++i) {
    const std::string pointer = "/waypoints/" + std::to_string(i);
    const auto& w = (*waypoints)[i];
    InstrumentState s = previous;
    s.abort = false;
    double t = 0.0;
    try {
      t = w.at("t").get<double>();
      s.tip = w.at("tip").get<core::Vec3>();
      if (w.contains("axis")) s.axis = w["axis"].get<core::Vec3>();
      if (w.contains("up")) s.up = w["up"].get<core::Vec3>();
      s.inflow = w.value("inflow", s.inflow);
      s.outflow = w.value("outflow", s.outflow);
      s.abort = w.value("abort", false);
      // The pedals, the laparoscopic tool in the working port, its jaws and the irrigation
      // valve of the suction–irrigation cannula: 0 or 1, held until a later waypoint changes them.
      read_switch(w, "activate", file, pointer, s.electrode);
      read_switch(w, "coagulate", file, pointer, s.coagulation);
      read_tool(w, file, pointer, s.tool);
      read_switch(w, "close", file, pointer, s.jaws_closed);
      read_switch(w, "irrigate", file, pointer, s.irrigating);
      if (w.contains("left")) read_second_port(w["left"], file, pointer + "/left", s.second);
      if (w.contains("camera"))
        read_camera(w["camera"], file, pointer + "/camera", optics_angle, s.camera);
      s.loop_extension = w.value("loop_extension", s.loop_extension);
      // A tip anchored on the tissue follows it; a tip without an anchor does not.
      s.follow = w.contains("tip_anchor") ? 1.0 : 0.0;
      s.anchor = s.follow > 0.0 ? w["tip_anchor"].get<core::Vec3>() : core::Vec3::Zero();
      s.anchor_body = s.follow > 0.0 ? w.value("tip_anchor_body", std::string()) : std::string();
      if (w.contains("look_at")) {
        const InstrumentState looking =
            look_at(s.tip, w["look_at"].get<core::Vec3>(), s.axis, optics_angle);
        s.axis = looking.axis;
        s.up = looking.up;
      }
    } catch (const nlohmann::json::exception& e) {
      fail(
          pointer,
          std::string(
              "waypoint needs \"t\" (s) and \"tip\" [x, y, z] (m), optional vectors and valves: ") +
              e.what());
    }
    if (!s.anchor.allFinite()) fail(pointer + "/tip_anchor", "the tip's anchor must be finite");
    if ((i == 0 && t != 0.0) || (i > 0 && !(t > script.times_.back())) || !s.tip.allFinite() ||
        !s.axis.allFinite() || s.axis.norm() == 0.0) {
      fail(pointer, "waypoint times must start at 0 and increase, tips and axes must be finite");
    }
    if (s.inflow < 0.0 || s.inflow > 1.0 || s.outflow < 0.0 || s.outflow > 1.0) {
      fail(pointer, "valve openings must lie in [0, 1]");
    }
    if (!(s.loop_extension >= 0.0 && s.loop_extension <= kMaxLoopExtension)) {
      fail(pointer + "/loop_extension", "the loop extension must lie in [0, 0.02] m");
    }
    orthonormalise(s);
    if (s.abort && script.abort_time_ < 0.0) script.abort_time_ = t;
    s.abort = false;  // abort is an event at its time, not a state to blend
    script.times_.push_back(t);
    script.states_.push_back(s);
    previous = s;
  }
  // The assistant holds the laparoscope from the start: the first camera a script gives is
  // where it is before that waypoint too.
  const auto first_held = std::find_if(script.states_.begin(), script.states_.end(),
                                       [](const InstrumentState& s) { return s.camera.held; });
  if (first_held != script.states_.end())
    for (auto it = script.states_.begin(); it != first_held; ++it)
      it->camera = first_held->camera;
  return script;
}

ScriptedTrajectory ScriptedTrajectory::read(const std::string& path, double optics_angle) {
  return from_json(core::read_json_file(path), path, optics_angle);
}

InstrumentState ScriptedTrajectory::state(long long /*step*/, double time) const {
  InstrumentState s;
  if (time <= times_.front()) {
    s = states_.front();
  } else if (time >= times_.back()) {
    s = states_.back();
  } else {
    const auto next = static_cast<std::size_t>(
        std::upper_bound(times_.begin(), times_.end(), time) - times_.begin());
    const double f = (time - times_[next - 1]) / (times_[next] - times_[next - 1]);
    s = blend(states_[next - 1], states_[next], f);
  }
  s.abort = abort_time_ >= 0.0 && time >= abort_time_;
  return s;
}

RecordedInput::RecordedInput(std::vector<std::pair<long long, InstrumentState>> changes)
    : changes_(std::move(changes)) {}

RecordedInput RecordedInput::from_tips(const std::vector<core::Vec3>& tips) {
  std::vector<std::pair<long long, InstrumentState>> changes(tips.size());
  for (std::size_t i = 0; i < tips.size(); ++i) {
    changes[i].first = static_cast<long long>(i);
    changes[i].second.tip = tips[i];
  }
  return RecordedInput(std::move(changes));
}

InstrumentState RecordedInput::state(long long step, double /*time*/) const {
  if (changes_.empty()) return {};
  const auto after =
      std::upper_bound(changes_.begin(), changes_.end(), step,
                       [](long long s, const auto& change) { return s < change.first; });
  return after == changes_.begin() ? changes_.front().second : std::prev(after)->second;
}

}  // namespace viscera::sim
