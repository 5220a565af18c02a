#include "core/library/asset_library.h"

#include <sqlite3.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <system_error>

#include "core/error.h"
#include "core/library/sqlite_statement.h"
#include "core/sha256.h"

namespace viscera::core {
namespace {

constexpr const char* kTypeNames[] = {"model", "material", "texture", "template"};

bool is_name_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '-';
}

void check_name(const std::string& name, const std::string& what, const std::string& entry) {
  if (name.empty() || name.size() > 128 ||
      !std::all_of(name.begin(), name.end(), is_name_character))
    throw UsageError(
        what + " \"" + name + "\" must be 1 to 128 characters of letters, digits, '.', '_' or '-'",
        {"", "", entry});
}

const char* const kSchema = R"sql(
CREATE TABLE schema_version(version INTEGER NOT NULL);
CREATE TABLE entries(
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL,
  version INTEGER NOT NULL,
  type TEXT NOT NULL CHECK(type IN ('model', 'material', 'texture', 'template')),
  provenance TEXT NOT NULL,
  payload_format TEXT NOT NULL,
  payload BLOB NOT NULL,
  payload_sha256 TEXT NOT NULL,
  thumbnail BLOB,
  tag_count INTEGER NOT NULL,
  UNIQUE(name, version));
CREATE TABLE tags(
  entry_id INTEGER NOT NULL REFERENCES entries(id) ON DELETE CASCADE,
  tag TEXT NOT NULL,
  PRIMARY KEY(entry_id, tag));
CREATE INDEX tags_by_tag ON tags(tag);
)sql";

std::vector<std::string> entry_tags(const SqliteDatabase& db, std::int64_t id) {
  SqliteStatement select(db, "SELECT tag FROM tags WHERE entry_id = ? ORDER BY tag");
  select.bind(1, id);
  std::vector<std::string> tags;
  while (select.step())
    tags.push_back(select.text(0));
  return tags;
}

/// Columns 1–9 of the summary queries below, in this order.
constexpr const char* kSummaryColumns =
    "id, name, type, version, provenance, payload_format, length(payload), payload_sha256, "
    "thumbnail IS NOT NULL";

AssetSummary read_summary(const SqliteDatabase& db, const SqliteStatement& row) {
  AssetSummary s;
  s.name = row.text(1);
  s.type = asset_type_from_string(row.text(2));
  s.version = static_cast<int>(row.integer(3));
  s.provenance = row.text(4);
  s.payload_format = row.text(5);
  s.payload_bytes = static_cast<std::uint64_t>(row.integer(6));
  s.payload_sha256 = row.text(7);
  s.has_thumbnail = row.integer(8) != 0;
  s.tags = entry_tags(db, row.integer(0));
  return s;
}

/// The rows of version ?2 of entry ?1, or of its latest version when ?2 is 0.
constexpr const char* kVersionRows =
    " FROM entries WHERE name = ?1 AND (version = ?2 OR (?2 = 0 AND version = (SELECT "
    "max(version) FROM entries WHERE name = ?1)))";

/// Binds `name` and `version` to a kVersionRows query and steps to its row; throws InputError
/// naming the library `file` and the entry when there is none.
void step_to_version(SqliteStatement& select, const std::string& name, int version,
                     const std::string& file) {
  select.bind(1, name);
  select.bind(2, std::int64_t{version});
  if (!select.step()) {
    throw InputError(version == 0 ? "the library has no entry \"" + name + "\""
                                  : "the library has no version " + std::to_string(version) +
                                        " of \"" + name + "\"",
                     {file, "", name});
  }
}

}  // namespace

std::string to_string(AssetType type) {
  return kTypeNames[static_cast<int>(type)];
}

AssetType asset_type_from_string(const std::string& name) {
  for (int i = 0; i < 4; ++i) {
    if (name == kTypeNames[i]) return static_cast<AssetType>(i);
  }
  throw UsageError("an asset type is model, material, texture or template, not \"" + name + "\"");
}

void check_asset_entry(const AssetEntry& entry) {
  const AssetSummary& s = entry.summary;
  check_name(s.name, "the name", s.name);
  for (const auto& tag : s.tags)
    check_name(tag, "the tag", s.name);
  if (s.payload_format.empty() || s.payload_format.size() > 16 ||
      !std::all_of(s.payload_format.begin(), s.payload_format.end(),
                   [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); }))
    throw UsageError("the payload format \"" + s.payload_format +
                         "\" must be a lower-case file extension without the dot",
                     {"", "", s.name});
  if (entry.payload.empty()) throw UsageError("the payload is empty", {"", "", s.name});
  static const std::string kPngSignature("\x89PNG\r\n\x1a\n", 8);
  if (!entry.thumbnail.empty() && entry.thumbnail.compare(0, 8, kPngSignature) != 0)
    throw UsageError("the thumbnail is not a PNG image", {"", "", s.name});
}

std::filesystem::path resolve_library_path(const std::string& option) {
  if (!option.empty()) return option;
  const char* env = std::getenv("VISCERA_LIBRARY");
  if (env != nullptr && *env != '\0') return env;
  const char* data_home = std::getenv("XDG_DATA_HOME");
  // The XDG base directory specification ignores relative values.
  if (data_home != nullptr && *data_home == '/')
    return std::filesystem::path(data_home) / "viscera" / "library.sqlite";
  const char* home = std::getenv("HOME");
  if (home != nullptr && *home != '\0')
    return std::filesystem::path(home) / ".local" / "share" / "viscera" / "library.sqlite";
  throw UsageError(
      "no library location: pass --library PATH or set VISCERA_LIBRARY, XDG_DATA_HOME or HOME");
}

AssetLibrary::AssetLibrary(const std::filesystem::path& path) : path_(path) {
  const std::string file = path.string();
  if (path.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec)
      throw OutputError("cannot create the library's folder: " + ec.message(), {file, "", ""});
  }
  db_ = open_sqlite_database(path);
  const SqliteDatabase db{db_, file};
  try {
    // WAL keeps readers off the writer's pages and makes every commit one append to the log,
    // which recovery replays or drops whole; FULL syncs the log at each commit.
    db.execute("PRAGMA journal_mode = WAL");
    db.execute("PRAGMA synchronous = FULL");
    db.execute("PRAGMA foreign_keys = ON");
    SqliteTransaction transaction(db);
    SqliteStatement has_schema(
        db, "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'schema_version'");
    has_schema.step();
    if (has_schema.integer(0) == 0) {
      SqliteStatement tables(db, "SELECT count(*) FROM sqlite_master");
      tables.step();
      if (tables.integer(0) != 0)
        throw InputError("an SQLite database, but not a Viscera asset library", {file, "", ""});
      db.execute(kSchema);
      db.execute("INSERT INTO schema_version(version) VALUES (" +
                 std::to_string(kAssetLibrarySchemaVersion) + ")");
    } else {
      SqliteStatement version(db, "SELECT version FROM schema_version");
      if (!version.step()) throw InputError("the library has no schema version", {file, "", ""});
      const auto found = version.integer(0);
      if (found > kAssetLibrarySchemaVersion)
        throw UnsupportedVersionError("library schema version " + std::to_string(found) +
                                          " is newer than this build reads (" +
                                          std::to_string(kAssetLibrarySchemaVersion) + ")",
                                      {file, "", ""});
    }
    transaction.commit();
  } catch (...) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw;
  }
}

AssetLibrary::~AssetLibrary() {
  if (db_ != nullptr) sqlite3_close(db_);
}

AssetSummary AssetLibrary::add(const AssetEntry& entry) {
  check_asset_entry(entry);
  const SqliteDatabase db{db_, path_.string()};
  AssetSummary s = entry.summary;
  std::set<std::string> unique_tags(s.tags.begin(), s.tags.end());
  s.tags.assign(unique_tags.begin(), unique_tags.end());
  s.payload_bytes = entry.payload.size();
  s.payload_sha256 = sha256_hex(entry.payload);
  s.has_thumbnail = !entry.thumbnail.empty();

  SqliteTransaction transaction(db);
  SqliteStatement existing(db, "SELECT type, max(version) FROM entries WHERE name = ?");
  existing.bind(1, s.name);
  existing.step();
  s.version = 1;
  if (!existing.is_null(0)) {
    if (existing.text(0) != to_string(s.type))
      throw UsageError("the library holds \"" + s.name + "\" as a " + existing.text(0) +
                           ", not a " + to_string(s.type),
                       {path_.string(), "", s.name});
    s.version = static_cast<int>(existing.integer(1)) + 1;
  }
  SqliteStatement insert(db,
                         "INSERT INTO entries(name, version, type, provenance, payload_format, "
                         "payload, payload_sha256, thumbnail, tag_count) "
                         "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert.bind(1, s.name);
  insert.bind(2, std::int64_t{s.version});
  insert.bind(3, to_string(s.type));
  insert.bind(4, s.provenance);
  insert.bind(5, s.payload_format);
  insert.bind_blob(6, entry.payload);
  insert.bind(7, s.payload_sha256);
  if (s.has_thumbnail) {
    insert.bind_blob(8, entry.thumbnail);
  } else {
    insert.bind_null(8);
  }
  insert.bind(9, static_cast<std::int64_t>(s.tags.size()));
  insert.step();
  const std::int64_t id = sqlite3_last_insert_rowid(db_);
  SqliteStatement tag_insert(db, "INSERT INTO tags(entry_id, tag) VALUES (?, ?)");
  for (const auto& tag : s.tags) {
    tag_insert.reset();
    tag_insert.bind(1, id);
    tag_insert.bind(2, tag);
    tag_insert.step();
  }
  transaction.commit();
  return s;
}

std::vector<AssetSummary> AssetLibrary::list(std::optional<AssetType> type, const std::string& tag,
                                             bool all_versions) const {
  const SqliteDatabase db{db_, path_.string()};
  std::string sql = std::string("SELECT ") + kSummaryColumns + " FROM entries e WHERE 1";
  if (type) sql += " AND type = :type";
  if (!tag.empty())
    sql += " AND EXISTS (SELECT 1 FROM tags t WHERE t.entry_id = e.id AND t.tag = :tag)";
  if (!all_versions)
    sql += " AND version = (SELECT max(version) FROM entries n WHERE n.name = e.name)";
  sql += " ORDER BY name, version";
  SqliteTransaction snapshot(db, false);  // one consistent view of entries and their tags
  SqliteStatement select(db, sql);
  if (type) select.bind_named(":type", to_string(*type));
  if (!tag.empty()) select.bind_named(":tag", tag);
  std::vector<AssetSummary> result;
  while (select.step())
    result.push_back(read_summary(db, select));
  return result;
}

AssetEntry AssetLibrary::get(const std::string& name, int version) const {
  const SqliteDatabase db{db_, path_.string()};
  SqliteTransaction snapshot(db, false);
  SqliteStatement select(
      db, std::string("SELECT ") + kSummaryColumns + ", payload, thumbnail" + kVersionRows);
  step_to_version(select, name, version, path_.string());
  AssetEntry entry;
  entry.summary = read_summary(db, select);
  entry.payload = select.blob(9);
  entry.thumbnail = select.blob(10);
  if (sha256_hex(entry.payload) != entry.summary.payload_sha256)
    throw ValidationError("the payload of version " + std::to_string(entry.summary.version) +
                              " does not match its checksum",
                          {path_.string(), "", name});
  return entry;
}

std::string AssetLibrary::thumbnail(const std::string& name, int version) const {
  const SqliteDatabase db{db_, path_.string()};
  SqliteTransaction snapshot(db, false);
  SqliteStatement select(db, std::string("SELECT thumbnail") + kVersionRows);
  step_to_version(select, name, version, path_.string());
  return select.blob(0);
}

int AssetLibrary::remove(const std::string& name, int version) {
  const SqliteDatabase db{db_, path_.string()};
  SqliteTransaction transaction(db);
  SqliteStatement erase(db, "DELETE FROM entries WHERE name = ?1 AND (?2 = 0 OR version = ?2)");
  erase.bind(1, name);
  erase.bind(2, std::int64_t{version});
  erase.step();
  const int removed = sqlite3_changes(db_);
  if (removed == 0) {
    throw InputError(version == 0 ? "the library has no entry \"" + name + "\""
                                  : "the library has no version " + std::to_string(version) +
                                        " of \"" + name + "\"",
                     {path_.string(), "", name});
  }
  transaction.commit();
  return removed;
}

std::string AssetLibrary::integrity_check() const {
  const SqliteDatabase db{db_, path_.string()};
  SqliteStatement check(db, "PRAGMA integrity_check");
  std::string result;
  while (check.step()) {
    if (!result.empty()) result += "; ";
    result += check.text(0);
  }
  return result;
}

}  // namespace viscera::core
