#pragma once
// The operative hysteroscopy sessions the polypectomy and myomectomy tests run: a shipped script
// placed at the patient's landmarks, run headless, and lookups into its report.

#include <algorithm>
#include <string>

#include "core/json_text.h"
#include "core/scenario/scenario.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "tests/support/test_paths.h"

namespace viscera::testing {

/// data/scripts/`script` (a resectoscope script at 12° optics, the tool on the uterus) on
/// `patient`, headless, for the script's length.
inline sim::SessionReport run_operative_script(const core::Scenario& patient,
                                               const std::string& script) {
  const std::string file = (source_dir() / "data/scripts" / script).string();
  const auto json =
      sim::resolve_script_landmarks(core::read_json_file(file), patient.landmarks, file);
  const auto input = sim::ScriptedTrajectory::from_json(json, file, 12.0);
  sim::HeadlessRunOptions options;
  options.duration = input.duration();
  options.instrument = &input;
  options.instrument_body = "uterus";
  return sim::run_headless(patient, options);
}

/// The resection of pathology `body` in a report with a cutting block (it must be there).
inline const sim::BodyResection& resection_of(const sim::SessionReport& report,
                                              const std::string& body) {
  const auto& bodies = report.cutting->bodies;
  return *std::find_if(bodies.begin(), bodies.end(), [&](const auto& b) { return b.body == body; });
}

/// The status of task `id` in the report ("" when it has none).
inline std::string task_status(const sim::SessionReport& report, const std::string& id) {
  for (const auto& t : report.tasks)
    if (t.id == id) return t.status;
  return "";
}

}  // namespace viscera::testing
