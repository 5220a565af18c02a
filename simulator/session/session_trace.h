#pragma once
/// Recorded sessions (DESIGN.md §5): the instrument's tip at every physics step and the state
/// hash every N steps, so that `viscera-sim replay` can run the session again in deterministic
/// mode and prove it bit-identical, checkpoint by checkpoint.
///
///   {"format": "viscera-trace", "version": 1, "package": path, "manifest_sha256": …,
///    "duration": s, "body": id, "stiffness": N/m, "checkpoint_interval": steps,
///    "tips": [[x, y, z], …], "checkpoints": [[step, hash], …], "final_state_hash": …}

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// Everything needed to replay a session and check it.
struct SessionTrace {
  std::string package;
  std::string manifest_sha256;  ///< identifies the package (its manifest lists every file's hash)
  double duration = 0.0;
  std::string body;
  double stiffness = 0.0;
  long long checkpoint_interval = 0;
  std::vector<core::Vec3> tips;
  std::vector<std::pair<long long, std::string>> checkpoints;
  std::string final_state_hash;
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
