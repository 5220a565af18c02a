#pragma once
/// Recorded sessions (DESIGN.md §5): the instrument's input and the state hash every N steps,
/// so that `viscera-sim replay` can run the session again in deterministic mode and prove it
/// bit-identical, checkpoint by checkpoint.
///
///   {"format": "viscera-trace", "version": 2, "package": path, "manifest_sha256": …,
///    "duration": s, "body": id, "stiffness": N/m, "perforation_depth": m, "force_warning": N,
///    "checkpoint_interval": steps,
///    "script": {viscera-script} or null,
///    "inputs": [[step, [tip], [axis], [up], inflow, outflow, abort], …],
///    "checkpoints": [[step, hash], …], "final_state_hash": …, "end_reason": …}
///
/// A scripted session stores its script (the input is a function of it); a live session stores
/// the instrument state at every step where it changed. Version 1 traces ("tips": one tip per
/// step) are still read.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simulator/session/instrument_input.h"

namespace viscera::sim {

/// Everything needed to replay a session and check it.
struct SessionTrace {
  std::string package;
  std::string manifest_sha256;  ///< identifies the package (its manifest lists every file's hash)
  double duration = 0.0;
  std::string body;
  double stiffness = 0.0;
  double perforation_depth = 0.0;  ///< m, the run's override (0: none)
  double force_warning = 0.0;      ///< N, the run's override (0: none)
  long long checkpoint_interval = 0;
  nlohmann::json script;      ///< the viscera-script of a scripted session, or null
  double optics_angle = 0.0;  ///< ° the script's look_at was resolved with
  std::vector<std::pair<long long, InstrumentState>> inputs;  ///< (step, state) changes
  std::vector<std::pair<long long, std::string>> checkpoints;
  std::string final_state_hash;
  std::string end_reason;

  /// The input that replays the session: the script, or the recorded states.
  std::unique_ptr<InstrumentInput> input() const;
};

/// SHA-256 of a package's manifest (folder or .vscz); throws core::InputError naming it.
std::string package_manifest_sha256(const std::filesystem::path& package);

nlohmann::json trace_to_json(const SessionTrace& trace);
/// Throws core::ValidationError naming `file` and the pointer of a bad member.
SessionTrace trace_from_json(const nlohmann::json& json, const std::string& file);

/// Writes through a temporary sibling; throws core::OutputError.
void write_trace(const SessionTrace& trace, const std::filesystem::path& path);
/// Throws core::InputError when unreadable, core::ValidationError when malformed.
SessionTrace read_trace(const std::filesystem::path& path);

}  // namespace viscera::sim
