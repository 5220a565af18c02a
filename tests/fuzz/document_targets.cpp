/// Fuzz targets for the documents a user hands the tools: scenario packages (folder and .vscz),
/// the scenario JSON inside them, instrument scripts, session traces, procedure definitions, the
/// UDP pose packet of a haptic device and the --input option.

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/package/scenario_package.h"
#include "core/scenario/procedure.h"
#include "core/scenario/scenario_json.h"
#include "core/sha256.h"
#include "simulator/haptics/device_packets.h"
#include "simulator/input/input_spec.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/session_trace.h"
#include "tests/fuzz/fuzz_target.h"

namespace viscera::fuzz {
namespace {

namespace fs = std::filesystem;

/// The input as JSON, or nothing when it is not JSON (a refusal the parsers report the same way).
std::optional<nlohmann::json> json_of(Bytes bytes) {
  auto json = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
  if (json.is_discarded()) return std::nullopt;
  return json;
}

/// Rewrites the checksums and sizes of the manifest in `folder` to those of the files present,
/// so mutated meshes and scenarios get past the checksum check into the readers behind it.
void restamp_manifest(const fs::path& folder) {
  const fs::path manifest = folder / "manifest.json";
  std::ifstream in(manifest);
  auto json = nlohmann::json::parse(in, nullptr, false);
  if (!json.is_object() || !json.contains("files") || !json["files"].is_object()) return;
  for (auto& [name, entry] : json["files"].items()) {
    const fs::path file = folder / name;
    std::error_code error;
    if (!entry.is_object() || name.find("..") != std::string::npos ||
        !fs::is_regular_file(file, error))
      continue;
    entry["sha256"] = core::sha256_file(file);
    entry["bytes"] = fs::file_size(file, error);
  }
  std::ofstream(manifest, std::ios::trunc) << json.dump(2);
}

const bool registered = [] {
  // A package folder: the input split at "\n--\n" into files, each chunk starting with its
  // package-relative path on one line (tests/fuzz/README.md shows the layout).
  register_target("package_folder", [](Bytes bytes) {
    const auto folder = input_named_folder(bytes);
    restamp_manifest(folder);
    expect_typed_errors([&] { core::read_package(folder); });
  });
  register_target("package_vscz", [](Bytes bytes) {
    const auto path = input_file(bytes, ".vscz");
    expect_typed_errors([&] { core::read_package(path); });
  });
  register_target("scenario_json", [](Bytes bytes) {
    const auto json = json_of(bytes);
    if (!json) return;
    expect_typed_errors([&] { core::scenario_from_json(*json, "scenario.json"); });
  });
  register_target("procedure_json", [](Bytes bytes) {
    const auto json = json_of(bytes);
    if (!json) return;
    expect_typed_errors([&] { core::procedure_from_json(*json, "procedure.json"); });
  });
  register_target("script_json", [](Bytes bytes) {
    const auto path = input_file(bytes, ".json");
    expect_typed_errors([&] { sim::ScriptedTrajectory::read(path.string()); });
  });
  register_target("trace_json", [](Bytes bytes) {
    const auto path = input_file(bytes, ".json");
    expect_typed_errors([&] { sim::read_trace(path); });
  });
  register_target("pose_packet", [](Bytes bytes) {
    // Any datagram: decoded or dropped (nullopt), never trusted half-way.
    const auto pose = sim::decode_pose(bytes);
    if (pose && !sim::decode_pose(sim::encode_pose(*pose))) std::abort();
  });
  register_target("input_option", [](Bytes bytes) {
    const std::string text(bytes.begin(), bytes.end());
    expect_typed_errors([&] { sim::parse_input_spec(text); });
  });
  return true;
}();

}  // namespace
}  // namespace viscera::fuzz
