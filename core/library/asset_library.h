#pragma once
/// The asset library (seed 001 §3.3: "each model, texture and elastodynamic material data can be
/// archived in an internal database for reuse or modification to create different training
/// scenarios"): an embedded SQLite database of models, materials, textures and templates.
///
/// Each entry has a name, a type, a version (adding a name again makes the next version), tags,
/// a provenance text, a payload (the file's bytes and its format, e.g. "json", "png", "vscz")
/// with its SHA-256, and an optional PNG thumbnail. The database runs in WAL mode and every
/// write is one transaction, so a process killed in the middle of a write leaves the previous
/// state intact; reads check each payload against its checksum.
///
/// Schema (version 1):
///   schema_version(version)
///   entries(id, name, version, type, provenance, payload_format, payload, payload_sha256,
///           thumbnail, tag_count)          UNIQUE(name, version)
///   tags(entry_id → entries.id ON DELETE CASCADE, tag)

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

struct sqlite3;

namespace viscera::core {

/// What an entry holds.
enum class AssetType { Model, Material, Texture, Template };
std::string to_string(AssetType type);
/// Parses "model", "material", "texture" or "template"; throws UsageError otherwise.
AssetType asset_type_from_string(const std::string& name);

/// Newest schema version this build reads and writes.
inline constexpr int kAssetLibrarySchemaVersion = 1;

/// An entry without its payload and thumbnail bytes (for listings).
struct AssetSummary {
  std::string name;  ///< [A-Za-z0-9._-]+, 1–128 characters
  AssetType type = AssetType::Model;
  int version = 0;                ///< 1, 2, … per name; 0 in an entry not yet added
  std::vector<std::string> tags;  ///< sorted, unique, each like a name
  std::string provenance;         ///< where it came from (free text, may be JSON)
  std::string payload_format;     ///< file extension without the dot, lower case, e.g. "json"
  std::uint64_t payload_bytes = 0;
  std::string payload_sha256;  ///< hex
  bool has_thumbnail = false;

  bool operator==(const AssetSummary&) const = default;
};

/// A complete entry.
struct AssetEntry {
  AssetSummary summary;
  std::string payload;    ///< the bytes
  std::string thumbnail;  ///< PNG bytes, or empty

  bool operator==(const AssetEntry&) const = default;
};

/// Throws UsageError naming the entry when a name or tag has characters outside
/// [A-Za-z0-9._-] or is empty or longer than 128, the format is not [a-z0-9]+, the payload is
/// empty, or the thumbnail is not PNG (its 8-byte signature).
void check_asset_entry(const AssetEntry& entry);

/// The database path from, in order: `option` when not empty (--library PATH), the environment
/// variable VISCERA_LIBRARY, $XDG_DATA_HOME/viscera/library.sqlite, and
/// $HOME/.local/share/viscera/library.sqlite. Throws UsageError when none applies.
std::filesystem::path resolve_library_path(const std::string& option = "");

/// An open asset library. Not thread-safe; several processes may share a database (SQLite
/// locks it; a writer waits up to 10 s for another).
class AssetLibrary {
 public:
  /// Opens the database at `path`, creating it and its folder when missing. Throws InputError
  /// naming the file when it is not an SQLite database or not a Viscera library,
  /// UnsupportedVersionError for a newer schema, OutputError when it cannot be created.
  explicit AssetLibrary(const std::filesystem::path& path);
  ~AssetLibrary();
  AssetLibrary(const AssetLibrary&) = delete;
  AssetLibrary& operator=(const AssetLibrary&) = delete;

  const std::filesystem::path& path() const { return path_; }

  /// Adds `entry` as the next version of its name in one transaction (the version field is
  /// ignored) and returns its summary. Throws as check_asset_entry, UsageError when the name
  /// exists with another type, OutputError when the write fails (nothing is added).
  AssetSummary add(const AssetEntry& entry);

  /// Entries sorted by name and version, optionally only one type and only those carrying
  /// `tag`; `all_versions` false keeps the newest version of each name.
  std::vector<AssetSummary> list(std::optional<AssetType> type = std::nullopt,
                                 const std::string& tag = "", bool all_versions = false) const;

  /// The entry `name` at `version` (0 = newest). Throws InputError naming the library and the
  /// entry when it is missing, ValidationError when its payload fails its checksum.
  AssetEntry get(const std::string& name, int version = 0) const;

  /// Only the PNG thumbnail of `name` at `version` (0 = newest), empty when it has none — for
  /// listings that should not read (and checksum) every payload. Throws InputError as get().
  std::string thumbnail(const std::string& name, int version = 0) const;

  /// Removes `name` at `version` (0 = every version) in one transaction; returns how many
  /// versions went. Throws InputError when there is none, OutputError when the write fails.
  int remove(const std::string& name, int version = 0);

  /// SQLite's `PRAGMA integrity_check`: "ok" or its findings.
  std::string integrity_check() const;

 private:
  std::filesystem::path path_;
  sqlite3* db_ = nullptr;
};

}  // namespace viscera::core
