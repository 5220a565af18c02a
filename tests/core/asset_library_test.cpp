#include "core/library/asset_library.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstdlib>
#include <fstream>
#include <optional>

#include "core/error.h"
#include "core/library/asset_entry_file.h"
#include "core/package/zip_archive.h"
#include "core/sha256.h"
#include "tests/support/test_paths.h"

namespace viscera::core {
namespace {

namespace fs = std::filesystem;

const std::string kPng("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);

AssetEntry make_entry(const std::string& name, AssetType type, const std::string& payload,
                      std::vector<std::string> tags = {}) {
  AssetEntry entry;
  entry.summary.name = name;
  entry.summary.type = type;
  entry.summary.tags = std::move(tags);
  entry.summary.provenance = "test";
  entry.summary.payload_format = "json";
  entry.payload = payload;
  return entry;
}

TEST(AssetLibrary, adding_a_name_again_makes_the_next_version_and_get_reads_either) {
  const fs::path file = testing::scratch_dir() / "sub" / "library.sqlite";
  AssetLibrary library(file);
  EXPECT_TRUE(fs::exists(file));
  auto first = make_entry("liver", AssetType::Material, "{\"a\":1}", {"abdomen", "soft"});
  first.thumbnail = kPng;
  const AssetSummary v1 = library.add(first);
  EXPECT_EQ(v1.version, 1);
  EXPECT_EQ(v1.payload_sha256, sha256_hex("{\"a\":1}"));
  EXPECT_EQ(v1.payload_bytes, 7u);
  const AssetSummary v2 =
      library.add(make_entry("liver", AssetType::Material, "{\"a\":2}", {"soft", "soft"}));
  EXPECT_EQ(v2.version, 2);
  EXPECT_EQ(v2.tags, std::vector<std::string>{"soft"});
  library.add(make_entry("tube", AssetType::Model, "{}", {"pipe"}));

  const AssetEntry newest = library.get("liver");
  EXPECT_EQ(newest.summary.version, 2);
  EXPECT_EQ(newest.payload, "{\"a\":2}");
  EXPECT_FALSE(newest.summary.has_thumbnail);
  const AssetEntry oldest = library.get("liver", 1);
  EXPECT_EQ(oldest.payload, "{\"a\":1}");
  EXPECT_EQ(oldest.thumbnail, kPng);
  EXPECT_EQ(oldest.summary.tags, (std::vector<std::string>{"abdomen", "soft"}));
  EXPECT_EQ(library.thumbnail("liver", 1), kPng);
  EXPECT_EQ(library.thumbnail("liver"), "");
  EXPECT_THROW(library.thumbnail("spleen"), InputError);

  const auto newest_only = library.list();
  ASSERT_EQ(newest_only.size(), 2u);
  EXPECT_EQ(newest_only[0].name, "liver");
  EXPECT_EQ(newest_only[0].version, 2);
  EXPECT_EQ(newest_only[1].name, "tube");
  EXPECT_EQ(library.list(std::nullopt, "", true).size(), 3u);
  EXPECT_EQ(library.list(AssetType::Model).size(), 1u);
  EXPECT_EQ(library.list(AssetType::Texture).size(), 0u);
  EXPECT_EQ(library.list(std::nullopt, "abdomen", true).size(), 1u);
  EXPECT_EQ(library.list(std::nullopt, "abdomen").size(), 0u);  // v2 dropped the tag
  EXPECT_EQ(library.integrity_check(), "ok");
}

TEST(AssetLibrary, entries_survive_reopening_and_rm_removes_versions) {
  const fs::path file = testing::scratch_dir() / "library.sqlite";
  {
    AssetLibrary library(file);
    library.add(make_entry("ball", AssetType::Model, "1"));
    library.add(make_entry("ball", AssetType::Model, "2"));
    library.add(make_entry("ball", AssetType::Model, "3"));
  }
  AssetLibrary library(file);
  EXPECT_EQ(library.get("ball").payload, "3");
  EXPECT_EQ(library.remove("ball", 2), 1);
  EXPECT_THROW(library.get("ball", 2), InputError);
  EXPECT_THROW(library.remove("ball", 2), InputError);
  EXPECT_EQ(library.list(std::nullopt, "", true).size(), 2u);
  EXPECT_EQ(library.add(make_entry("ball", AssetType::Model, "4")).version, 4);
  EXPECT_EQ(library.remove("ball"), 3);
  EXPECT_TRUE(library.list().empty());
  EXPECT_THROW(library.get("ball"), InputError);
}

TEST(AssetLibrary, refuses_bad_entries_and_files_that_are_not_libraries) {
  const fs::path dir = testing::scratch_dir();
  AssetLibrary library(dir / "library.sqlite");
  EXPECT_THROW(library.add(make_entry("bad name", AssetType::Model, "x")), UsageError);
  EXPECT_THROW(library.add(make_entry("", AssetType::Model, "x")), UsageError);
  EXPECT_THROW(library.add(make_entry("ok", AssetType::Model, "x", {"a/b"})), UsageError);
  EXPECT_THROW(library.add(make_entry("ok", AssetType::Model, "")), UsageError);
  auto not_png = make_entry("ok", AssetType::Model, "x");
  not_png.thumbnail = "GIF89a";
  EXPECT_THROW(library.add(not_png), UsageError);
  library.add(make_entry("ok", AssetType::Model, "x"));
  EXPECT_THROW(library.add(make_entry("ok", AssetType::Texture, "y")), UsageError);
  EXPECT_EQ(library.list(std::nullopt, "", true).size(), 1u);

  {
    std::ofstream text(dir / "notes.txt");
    text << "these are not the pages of a database, just some words long enough to be read.\n";
  }
  EXPECT_THROW(AssetLibrary(dir / "notes.txt"), InputError);
  // An SQLite database of something else is not taken over.
  {
    sqlite3* other = nullptr;
    ASSERT_EQ(sqlite3_open((dir / "other.sqlite").c_str(), &other), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(other, "CREATE TABLE patients(name TEXT)", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(other);
  }
  EXPECT_THROW(AssetLibrary(dir / "other.sqlite"), InputError);
  // A library of a newer schema is refused by name.
  { AssetLibrary newer(dir / "newer.sqlite"); }
  {
    sqlite3* newer = nullptr;
    ASSERT_EQ(sqlite3_open((dir / "newer.sqlite").c_str(), &newer), SQLITE_OK);
    ASSERT_EQ(
        sqlite3_exec(newer, "UPDATE schema_version SET version = 99", nullptr, nullptr, nullptr),
        SQLITE_OK);
    sqlite3_close(newer);
  }
  EXPECT_THROW(AssetLibrary(dir / "newer.sqlite"), UnsupportedVersionError);
  try {
    AssetLibrary(dir / "notes.txt");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
  }
}

TEST(AssetLibrary, library_path_comes_from_the_option_then_the_environment) {
  struct Saved {
    const char* name;
    std::optional<std::string> value;
  };
  std::vector<Saved> saved;
  for (const char* name : {"VISCERA_LIBRARY", "XDG_DATA_HOME", "HOME"}) {
    const char* v = std::getenv(name);
    saved.push_back({name, v ? std::optional<std::string>(v) : std::nullopt});
  }
  ::setenv("VISCERA_LIBRARY", "/a/lib.sqlite", 1);
  ::setenv("XDG_DATA_HOME", "/data", 1);
  ::setenv("HOME", "/home/u", 1);
  EXPECT_EQ(resolve_library_path("/x.sqlite"), fs::path("/x.sqlite"));
  EXPECT_EQ(resolve_library_path(), fs::path("/a/lib.sqlite"));
  ::unsetenv("VISCERA_LIBRARY");
  EXPECT_EQ(resolve_library_path(), fs::path("/data/viscera/library.sqlite"));
  ::setenv("XDG_DATA_HOME", "relative", 1);  // ignored, as the XDG specification says
  EXPECT_EQ(resolve_library_path(), fs::path("/home/u/.local/share/viscera/library.sqlite"));
  ::unsetenv("XDG_DATA_HOME");
  ::unsetenv("HOME");
  EXPECT_THROW(resolve_library_path(), UsageError);
  for (const auto& s : saved) {
    if (s.value) {
      ::setenv(s.name, s.value->c_str(), 1);
    } else {
      ::unsetenv(s.name);
    }
  }
}

TEST(AssetEntryFile, exports_the_same_bytes_twice_and_imports_into_another_library) {
  const fs::path dir = testing::scratch_dir();
  AssetLibrary source(dir / "a.sqlite");
  auto entry =
      make_entry("myometrium", AssetType::Material, std::string("{\"x\":\0}", 7), {"uterus"});
  entry.thumbnail = kPng;
  source.add(entry);
  source.add(entry);
  const AssetEntry stored = source.get("myometrium");
  export_asset_entry(stored, dir / "one.vasset");
  export_asset_entry(stored, dir / "two.vasset");
  EXPECT_EQ(sha256_file(dir / "one.vasset"), sha256_file(dir / "two.vasset"));
  for (const auto& item : fs::directory_iterator(dir))  // no temporary left beside
    EXPECT_NE(item.path().filename().string().front(), '.') << item.path();

  const AssetEntry imported = import_asset_entry(dir / "one.vasset");
  EXPECT_EQ(imported, stored);
  AssetLibrary target(dir / "b.sqlite");
  const AssetSummary added = target.add(imported);
  EXPECT_EQ(added.version, 1);  // versions count per library
  EXPECT_EQ(target.get("myometrium").payload, entry.payload);
}

TEST(AssetEntryFile, a_payload_that_fails_its_checksum_is_refused) {
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = dir / "entry";
  fs::create_directories(folder);
  std::ofstream(folder / "entry.json")
      << R"({"format": "viscera-library-entry", "version": 1, "name": "x", "type": "model",
             "entry_version": 1, "tags": [], "provenance": "", "payload": "payload.json",
             "payload_format": "json", "payload_sha256": ")"
      << sha256_hex("{}") << R"(", "thumbnail": null})";
  std::ofstream(folder / "payload.json") << "{ }";
  zip_folder(folder, dir / "bad.vasset");
  EXPECT_THROW(import_asset_entry(dir / "bad.vasset"), ValidationError);
  EXPECT_THROW(import_asset_entry(dir / "missing.vasset"), InputError);
}

}  // namespace
}  // namespace viscera::core
