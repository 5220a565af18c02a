#include "tests/bench/session_scripts.h"

#include <fstream>

#include "simulator/session/instrument_input.h"
#include "templates/template_catalog.h"

namespace viscera::bench {

const core::Scenario& hysteroscopy_patient() {
  static const core::Scenario scenario = templates::build_from_template("hysteroscopy", {}, 1);
  return scenario;
}

nlohmann::json hysteroscopy_script(const std::string& who) {
  const std::string path =
      std::string(VISCERA_SOURCE_DIR) + "/data/scripts/hysteroscopy-" + who + ".json";
  std::ifstream in(path);
  return sim::resolve_script_landmarks(nlohmann::json::parse(in), hysteroscopy_patient().landmarks,
                                       path);
}

nlohmann::json repeated(nlohmann::json script, double seconds) {
  const nlohmann::json once = script["waypoints"];
  const double length = once.back()["t"].get<double>() + 0.5;
  nlohmann::json waypoints = nlohmann::json::array();
  for (double offset = 0.0; offset < seconds; offset += length) {
    for (auto point : once) {
      point["t"] = point["t"].get<double>() + offset;
      waypoints.push_back(point);
    }
  }
  script["waypoints"] = waypoints;
  return script;
}

sim::HeadlessRunOptions scripted_run(const sim::ScriptedTrajectory& input, double duration) {
  sim::HeadlessRunOptions options;
  options.duration = duration;
  options.instrument = &input;
  options.instrument_body = input.body();
  options.instrument_stiffness = input.stiffness();
  options.force_warning = input.force_warning();
  options.end_when_complete = false;
  return options;
}

}  // namespace viscera::bench
