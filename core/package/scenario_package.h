#pragma once
/// The scenario package: the contract between studio and simulator (DESIGN.md §4).
///
/// A directory NAME.vscene/ or the same zipped as NAME.vscz:
///   manifest.json                 format "viscera-scenario", version, the Scenario, sha256 of
///                                 every other file
///   objects/<id>/surface.vtp      visual mesh: normals, UVs, embedding arrays (VTK XML)
///   objects/<id>/body.vtu         simulation mesh: tets, per-node mass, fixed flags (VTK XML)
///   textures/<id>_{albedo,normal,specular}.png
///
/// Writes go to a temporary sibling and are renamed into place, so a failed write leaves no
/// partial package. Reads check the manifest against docs/scenario-package.schema.json, every
/// reference between parts, and every checksum; errors carry the file and JSON pointer.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::core {

/// Format name and the newest manifest version this build reads and writes.
inline constexpr const char* kPackageFormat = "viscera-scenario";
inline constexpr int kPackageVersion = 1;

/// Zip entries larger than this (uncompressed) are refused, and so are archives whose entries
/// add up to more than kMaxPackageBytes.
inline constexpr std::uint64_t kMaxZipEntryBytes = 2ULL << 30;  // 2 GiB
inline constexpr std::uint64_t kMaxPackageBytes = 8ULL << 30;   // 8 GiB

/// One problem found by validate_package().
struct PackageIssue {
  std::string file;          ///< path inside the package, e.g. "manifest.json"
  std::string json_pointer;  ///< e.g. "/scenario/objects/3/material", or empty
  std::string message;       ///< one sentence

  bool operator==(const PackageIssue&) const = default;
};

/// Summary of a package for `viscera info`.
struct PackageSummary {
  std::string format;
  int version = 0;
  std::string name;
  std::string procedure;
  std::string template_name;
  std::uint64_t seed = 0;
  int object_count = 0;
  std::int64_t surface_triangles = 0;
  std::int64_t body_nodes = 0;
  std::int64_t body_tets = 0;
  int file_count = 0;
  std::uint64_t total_bytes = 0;
};

/// Writes `scenario` as a package; a path ending in .vscz is zipped, anything else is a folder.
/// Replaces an existing package at `path` only after the new one is complete.
/// Throws OutputError (nothing left behind) or ValidationError if the scenario is inconsistent.
void write_package(const Scenario& scenario, const std::filesystem::path& path,
                   Progress& progress = Progress::none());

/// Same, with extra files (package-relative path → bytes, e.g. "textures/ball_albedo.png")
/// written into the package and listed with their checksums.
void write_package(const Scenario& scenario, const std::map<std::string, std::string>& extra_files,
                   const std::filesystem::path& path, Progress& progress = Progress::none());

/// Reads a package folder or .vscz, checking schema, references, versions and checksums.
/// Throws InputError (unreadable, malformed, unsafe zip), UnsupportedVersionError (newer
/// version) or ValidationError (schema, references, checksums) naming the file and pointer.
Scenario read_package(const std::filesystem::path& path, Progress& progress = Progress::none());

/// Checks a package without stopping at the first problem. Empty result = valid.
/// Throws InputError only when the package cannot be opened at all.
std::vector<PackageIssue> validate_package(const std::filesystem::path& path);

/// Reads only the manifest and file sizes.
PackageSummary summarize_package(const std::filesystem::path& path);

/// Zips a package folder into a .vscz (checksums verified first).
void pack_package(const std::filesystem::path& folder, const std::filesystem::path& vscz);
/// Unzips a .vscz into a folder (safety and checksums verified first).
void unpack_package(const std::filesystem::path& vscz, const std::filesystem::path& folder);

}  // namespace viscera::core
