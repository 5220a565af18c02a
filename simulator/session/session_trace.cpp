#include "simulator/session/session_trace.h"

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/json_eigen.h"
#include "core/package/package_manifest.h"
#include "core/package/zip_archive.h"
#include "core/sha256.h"

namespace viscera::sim {

std::string package_manifest_sha256(const std::filesystem::path& package) {
  if (std::filesystem::is_directory(package)) return core::sha256_file(package / core::kManifestFile);
  if (!std::filesystem::exists(package)) throw core::InputError("no such package", {package.string(), "", ""});
  return core::sha256_hex(core::read_zip_entry(package, core::kManifestFile, {core::kMaxZipEntryBytes, core::kMaxPackageBytes}));
}

nlohmann::json trace_to_json(const SessionTrace& t) {
  nlohmann::json checkpoints = nlohmann::json::array();
  for (const auto& [step, hash] : t.checkpoints) checkpoints.push_back({step, hash});
  return {{"format", "viscera-trace"}, {"version", 1},
          {"package", t.package},      {"manifest_sha256", t.manifest_sha256},
          {"duration", t.duration},    {"body", t.body},
          {"stiffness", t.stiffness},  {"checkpoint_interval", t.checkpoint_interval},
          {"tips", t.tips},            {"checkpoints", checkpoints},
          {"final_state_hash", t.final_state_hash}};
}

SessionTrace trace_from_json(const nlohmann::json& j, const std::string& file) {
  if (!j.is_object() || j.value("format", std::string()) != "viscera-trace") {
    throw core::ValidationError("not a Viscera session trace", {file, "/format", ""});
  }
  if (j.value("version", 0) != 1) throw core::ValidationError("trace version must be 1", {file, "/version", ""});
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
    member = "tips";
    j.at(member).get_to(t.tips);
    member = "checkpoints";
    for (const auto& c : j.at(member)) t.checkpoints.emplace_back(c.at(0).get<long long>(), c.at(1).get<std::string>());
    member = "final_state_hash";
    j.at(member).get_to(t.final_state_hash);
  } catch (const nlohmann::json::exception& e) {
    throw core::ValidationError(std::string("cannot read: ") + e.what(), {file, "/" + member, ""});
  }
  return t;
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
  std::ifstream in(path, std::ios::binary);
  if (!in) throw core::InputError("cannot open trace", {path.string(), "", ""});
  std::stringstream text;
  text << in.rdbuf();
  try {
    return trace_from_json(nlohmann::json::parse(text.str()), path.string());
  } catch (const nlohmann::json::parse_error& e) {
    throw core::InputError("not valid JSON (syntax error at byte " + std::to_string(e.byte) + ")", {path.string(), "", ""});
  }
}

}  // namespace viscera::sim
