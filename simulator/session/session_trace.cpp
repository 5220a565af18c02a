#include "simulator/session/session_trace.h"

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/json_eigen.h"
#include "core/json_numbers.h"
#include "core/json_text.h"
#include "core/package/package_manifest.h"
#include "core/package/zip_archive.h"
#include "core/sha256.h"

namespace viscera::sim {

std::string package_manifest_sha256(const std::filesystem::path& package) {
  if (std::filesystem::is_directory(package))
    return core::sha256_file(package / core::kManifestFile);
  if (!std::filesystem::exists(package))
    throw core::InputError("no such package", {package.string(), "", ""});
  return core::sha256_hex(core::read_zip_entry(package, core::kManifestFile,
                                               {core::kMaxZipEntryBytes, core::kMaxPackageBytes}));
}

namespace {

nlohmann::json state_to_json(long long step, const InstrumentState& s) {
  return {step,
          s.tip,
          s.axis,
          s.up,
          s.inflow,
          s.outflow,
          s.abort,
          s.electrode,
          s.loop_extension,
          s.coagulation,
          std::string(tool_name(s.tool)),
          s.jaws_closed,
          s.irrigating,
          s.follow,
          s.anchor,
          s.anchor_body,
          nlohmann::json::array({s.second.inserted, s.second.tip, s.second.axis, s.second.up,
                                 std::string(tool_name(s.second.tool)), s.second.jaws_closed,
                                 s.second.coagulation, s.second.electrode, s.second.irrigating}),
          nlohmann::json::array({s.camera.held, s.camera.tip, s.camera.axis, s.camera.up})};
}

std::pair<long long, InstrumentState> state_from_json(const nlohmann::json& j) {
  InstrumentState s;
  j.at(1).get_to(s.tip);
  j.at(2).get_to(s.axis);
  j.at(3).get_to(s.up);
  j.at(4).get_to(s.inflow);
  j.at(5).get_to(s.outflow);
  j.at(6).get_to(s.abort);
  // Traces before the resection loop have 7 members.
  if (j.size() > 7) j.at(7).get_to(s.electrode);
  if (j.size() > 8) j.at(8).get_to(s.loop_extension);
  if (j.size() > 9) j.at(9).get_to(s.coagulation);  // since the coagulation pedal
  if (j.size() > 11) {                              // since the laparoscopic tools
    const auto tool = tool_from_name(j.at(10).get<std::string>());
    if (!tool) throw core::ValidationError("an input names an unknown laparoscopic tool", {});
    s.tool = *tool;
    j.at(11).get_to(s.jaws_closed);
  }
  if (j.size() > 12) j.at(12).get_to(s.irrigating);  // since the suction–irrigation cannula
  if (j.size() > 15) {                               // since tips that follow the tissue
    j.at(13).get_to(s.follow);
    j.at(14).get_to(s.anchor);
    j.at(15).get_to(s.anchor_body);
  }
  if (j.size() > 16) {  // since the second instrument port
    const nlohmann::json& port = j.at(16);
    port.at(0).get_to(s.second.inserted);
    port.at(1).get_to(s.second.tip);
    port.at(2).get_to(s.second.axis);
    port.at(3).get_to(s.second.up);
    const auto tool = tool_from_name(port.at(4).get<std::string>());
    if (!tool) throw core::ValidationError("an input names an unknown laparoscopic tool", {});
    s.second.tool = *tool;
    port.at(5).get_to(s.second.jaws_closed);
    port.at(6).get_to(s.second.coagulation);
    port.at(7).get_to(s.second.electrode);
    port.at(8).get_to(s.second.irrigating);
  }
  if (j.size() > 17) {  // since the laparoscope held as a camera of its own
    const nlohmann::json& camera = j.at(17);
    camera.at(0).get_to(s.camera.held);
    camera.at(1).get_to(s.camera.tip);
    camera.at(2).get_to(s.camera.axis);
    camera.at(3).get_to(s.camera.up);
  }
  return {core::whole_number<long long>(j.at(0), "", ""), s};
}

}  // namespace

std::unique_ptr<InstrumentInput> SessionTrace::input() const {
  if (!script.is_null()) {
    return std::make_unique<ScriptedTrajectory>(
        ScriptedTrajectory::from_json(script, "the trace's script", optics_angle));
  }
  return std::make_unique<RecordedInput>(inputs);
}

nlohmann::json trace_to_json(const SessionTrace& t) {
  nlohmann::json checkpoints = nlohmann::json::array();
  for (const auto& [step, hash] : t.checkpoints)
    checkpoints.push_back({step, hash});
  nlohmann::json inputs = nlohmann::json::array();
  for (const auto& [step, state] : t.inputs)
    inputs.push_back(state_to_json(step, state));
  return {{"format", "viscera-trace"},
          {"version", 2},
          {"package", t.package},
          {"manifest_sha256", t.manifest_sha256},
          {"duration", t.duration},
          {"body", t.body},
          {"stiffness", t.stiffness},
          {"perforation_depth", t.perforation_depth},
          {"force_warning", t.force_warning},
          {"checkpoint_interval", t.checkpoint_interval},
          {"script", t.script},
          {"optics_angle", t.optics_angle},
          {"inputs", inputs},
          {"checkpoints", checkpoints},
          {"final_state_hash", t.final_state_hash},
          {"end_reason", t.end_reason}};
}

namespace {

/// trace_from_json without the net for nlohmann's type errors.
SessionTrace trace_from_checked_json(const nlohmann::json& j, const std::string& file) {
  if (!core::has_format(j, "viscera-trace")) {
    throw core::ValidationError("not a Viscera session trace", {file, "/format", ""});
  }
  const int version = core::format_version(j);
  if (version != 1 && version != 2)
    throw core::ValidationError("trace version must be 1 or 2", {file, "/version", ""});
  SessionTrace t;
  std::string member;
  try {
    member = "package";
    j.at(member).get_to(t.package);
    member = "manifest_sha256";
    j.at(member).get_to(t.manifest_sha256);
    member = "duration";
    j.at(member).get_to(t.duration);
    member = "body";
    j.at(member).get_to(t.body);
    member = "stiffness";
    j.at(member).get_to(t.stiffness);
    member = "checkpoint_interval";
    j.at(member).get_to(t.checkpoint_interval);
    if (version == 1) {
      member = "tips";
      const auto tips = j.at(member).get<std::vector<core::Vec3>>();
      for (std::size_t i = 0; i < tips.size(); ++i) {
        InstrumentState s;
        s.tip = tips[i];
        t.inputs.emplace_back(static_cast<long long>(i), s);
      }
    } else {
      member = "perforation_depth";
      j.at(member).get_to(t.perforation_depth);
      member = "force_warning";
      j.at(member).get_to(t.force_warning);
      member = "script";
      t.script = j.at(member);
      member = "optics_angle";
      t.optics_angle = j.value(member, 0.0);
      member = "inputs";
      for (const auto& change : j.at(member))
        t.inputs.push_back(state_from_json(change));
      member = "end_reason";
      t.end_reason = j.value(member, std::string());
    }
    member = "checkpoints";
    for (const auto& c : j.at(member))
      t.checkpoints.emplace_back(core::whole_number<long long>(c.at(0), "", ""),
                                 c.at(1).get<std::string>());
    member = "final_state_hash";
    j.at(member).get_to(t.final_state_hash);
  } catch (const nlohmann::json::exception& e) {
    throw core::ValidationError(std::string("cannot read: ") + e.what(), {file, "/" + member, ""});
  } catch (const core::ValidationError& e) {  // a step number that is not a whole number
    throw core::ValidationError(e.reason(), {file, "/" + member, ""});
  }
  if (t.script.is_null() && t.inputs.empty() && !t.body.empty()) {
    throw core::ValidationError("the trace has an instrument but neither a script nor inputs",
                                {file, "/inputs", ""});
  }
  return t;
}

}  // namespace

SessionTrace trace_from_json(const nlohmann::json& j, const std::string& file) {
  try {
    return trace_from_checked_json(j, file);
  } catch (const nlohmann::json::exception& e) {  // a member of the wrong JSON type
    throw core::ValidationError(std::string("cannot read the trace: ") + e.what(), {file, "", ""});
  }
}

void write_trace(const SessionTrace& trace, const std::filesystem::path& path) {
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << trace_to_json(trace).dump() << "\n";
    if (!out) throw core::OutputError("cannot write the trace", {path.string(), "", ""});
  }
  std::filesystem::rename(temporary, path);
}

SessionTrace read_trace(const std::filesystem::path& path) {
  return trace_from_json(core::read_json_file(path.string()), path.string());
}

}  // namespace viscera::sim
