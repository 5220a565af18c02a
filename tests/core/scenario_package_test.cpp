#include "core/package/scenario_package.h"

#include <gtest/gtest.h>
#include <zip.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/package/zip_archive.h"
#include "core/scenario/scenario_json.h"
#include "tests/core/scenario_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::core {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

nlohmann::json read_manifest(const fs::path& package) {
  return nlohmann::json::parse(read_text(package / "manifest.json"));
}
void write_manifest(const fs::path& package, const nlohmann::json& manifest) {
  write_text(package / "manifest.json", manifest.dump(2));
}

/// Expects `work` to throw E whose message contains every fragment.
template <typename E, typename Work>
void expect_error(Work&& work, std::initializer_list<std::string> fragments) {
  try {
    work();
    ADD_FAILURE() << "no error thrown";
  } catch (const E& e) {
    for (const auto& fragment : fragments)
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

/// Only the package itself may remain in `dir`: no temporaries of failed or finished writes.
std::vector<std::string> entries_of(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class PackageRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(PackageRoundTrip, keeps_every_field_of_every_part) {
  const auto dir = viscera::testing::scratch_dir();
  const Scenario original = viscera::testing::full_scenario();
  const fs::path path = dir / ("full" + GetParam());
  write_package(original, path);
  const Scenario back = read_package(path);
  EXPECT_EQ(back.metadata, original.metadata);
  EXPECT_EQ(back.materials, original.materials);
  EXPECT_EQ(back.textures, original.textures);
  EXPECT_EQ(back.vessel_trees, original.vessel_trees);
  EXPECT_EQ(back.active_deformations, original.active_deformations);
  EXPECT_EQ(back.pathologies, original.pathologies);
  EXPECT_EQ(back.connections, original.connections);
  EXPECT_EQ(back.fluid, original.fluid);
  EXPECT_EQ(back.session, original.session);
  EXPECT_EQ(back.variability, original.variability);
  EXPECT_EQ(back.provenance, original.provenance);
  ASSERT_EQ(back.objects.size(), original.objects.size());
  for (std::size_t i = 0; i < back.objects.size(); ++i) {
    EXPECT_EQ(back.objects[i].surface, original.objects[i].surface) << i;
    EXPECT_EQ(back.objects[i].body, original.objects[i].body) << i;
    EXPECT_EQ(back.objects[i].embedding, original.objects[i].embedding) << i;
    EXPECT_EQ(back.objects[i].hydrometra, original.objects[i].hydrometra) << i;
  }
  EXPECT_EQ(back, original);
  EXPECT_EQ(entries_of(dir), std::vector<std::string>{path.filename().string()});
}

TEST_P(PackageRoundTrip, writing_twice_gives_identical_bytes) {
  const auto dir = viscera::testing::scratch_dir();
  const Scenario scenario = viscera::testing::full_scenario();
  write_package(scenario, dir / ("a" + GetParam()));
  write_package(scenario, dir / ("b" + GetParam()));
  if (GetParam() == ".vscz") {
    EXPECT_EQ(read_text(dir / "a.vscz"), read_text(dir / "b.vscz"));
  } else {
    for (const auto& file : {"manifest.json", "objects/uterus/surface.vtp",
                             "objects/uterus/body.vtu", "objects/uterus/hydrometra.bin"}) {
      EXPECT_EQ(read_text(dir / "a.vscene" / file), read_text(dir / "b.vscene" / file)) << file;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Forms, PackageRoundTrip, ::testing::Values(".vscene", ".vscz"),
                         [](const auto& form) { return form.param.substr(1); });

class BadPackage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = viscera::testing::scratch_dir();
    package_ = dir_ / "p.vscene";
    write_package(viscera::testing::full_scenario(), package_);
  }
  fs::path dir_, package_;
};

TEST_F(BadPackage, corrupt_manifest_is_unreadable_input_naming_the_file) {
  write_text(package_ / "manifest.json", "{\"format\": \"viscera-scenario\", ");
  expect_error<InputError>([&] { read_package(package_); }, {"manifest.json", "not valid JSON"});
  EXPECT_THROW(validate_package(package_), InputError);
}

TEST_F(BadPackage, wrong_checksum_names_the_changed_file) {
  std::ofstream(package_ / "objects/uterus/body.vtu", std::ios::app) << " ";
  expect_error<ValidationError>([&] { read_package(package_); },
                                {"objects/uterus/body.vtu", "checksum"});
}

TEST_F(BadPackage, newer_version_is_refused_with_the_version_pointer) {
  auto manifest = read_manifest(package_);
  manifest["version"] = 7;
  write_manifest(package_, manifest);
  expect_error<UnsupportedVersionError>(
      [&] { read_package(package_); },
      {"manifest.json", "/version", "version 7 is newer", "update Viscera"});
}

TEST_F(BadPackage, missing_file_is_named) {
  fs::remove(package_ / "objects/uterus/surface.vtp");
  expect_error<ValidationError>([&] { read_package(package_); },
                                {"objects/uterus/surface.vtp", "missing"});
}

TEST_F(BadPackage, unknown_material_reference_carries_its_json_pointer) {
  auto manifest = read_manifest(package_);
  manifest["scenario"]["objects"][0]["material"] = "myo";
  write_manifest(package_, manifest);
  expect_error<ValidationError>(
      [&] { read_package(package_); },
      {"manifest.json", "/scenario/objects/0/material", "unknown material id \"myo\""});
  const auto issues = validate_package(package_);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].json_pointer, "/scenario/objects/0/material");
}

TEST_F(BadPackage, schema_violations_are_all_reported_with_pointers) {
  auto manifest = read_manifest(package_);
  manifest["scenario"]["materials"]["soft"]["density"] = "heavy";
  manifest["scenario"]["session"]["time_step"] = -1;
  manifest["scenario"]["objects"][1]["role"] = "spleen";
  write_manifest(package_, manifest);
  const auto issues = validate_package(package_);
  std::vector<std::string> pointers;
  for (const auto& issue : issues)
    pointers.push_back(issue.json_pointer);
  EXPECT_NE(std::find(pointers.begin(), pointers.end(), "/scenario/materials/soft/density"),
            pointers.end());
  EXPECT_NE(std::find(pointers.begin(), pointers.end(), "/scenario/session/time_step"),
            pointers.end());
  EXPECT_NE(std::find(pointers.begin(), pointers.end(), "/scenario/objects/1/role"),
            pointers.end());
  expect_error<ValidationError>([&] { read_package(package_); }, {"manifest.json", "/scenario/"});
}

TEST_F(BadPackage, unlisted_file_is_reported) {
  write_text(package_ / "objects/uterus/extra.txt", "smuggled");
  const auto issues = validate_package(package_);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].file, "objects/uterus/extra.txt");
}

TEST_F(BadPackage, wrong_format_name_is_refused) {
  auto manifest = read_manifest(package_);
  manifest["format"] = "something-else";
  write_manifest(package_, manifest);
  expect_error<InputError>([&] { read_package(package_); },
                           {"/format", "not a Viscera scenario package"});
}

/// Writes a zip holding one entry `name` with some bytes, optionally marked as a symlink.
void write_crafted_zip(const fs::path& path, const std::string& name, bool as_symlink) {
  int error = 0;
  zip_t* archive = zip_open(path.string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(archive, nullptr);
  static const char kBytes[] = "../../etc/passwd";
  zip_source_t* source = zip_source_buffer(archive, kBytes, sizeof kBytes - 1, 0);
  const zip_int64_t index = zip_file_add(archive, name.c_str(), source, ZIP_FL_ENC_UTF_8);
  ASSERT_GE(index, 0);
  if (as_symlink) {
    zip_file_set_external_attributes(archive, static_cast<zip_uint64_t>(index), 0, ZIP_OPSYS_UNIX,
                                     0120777u << 16);
  }
  ASSERT_EQ(zip_close(archive), 0);
}

TEST(UnsafeZip, dot_dot_entry_is_refused_and_nothing_escapes) {
  const auto dir = viscera::testing::scratch_dir();
  write_crafted_zip(dir / "evil.vscz", "objects/../../escaped.txt", false);
  expect_error<InputError>([&] { read_package(dir / "evil.vscz"); },
                           {"evil.vscz", "objects/../../escaped.txt", "outside"});
  EXPECT_THROW(unpack_package(dir / "evil.vscz", dir / "out"), InputError);
  EXPECT_FALSE(fs::exists(dir.parent_path() / "escaped.txt"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(UnsafeZip, absolute_path_is_refused) {
  const auto dir = viscera::testing::scratch_dir();
  write_crafted_zip(dir / "abs.vscz", "/tmp/viscera-absolute.txt", false);
  expect_error<InputError>([&] { read_package(dir / "abs.vscz"); },
                           {"abs.vscz", "/tmp/viscera-absolute.txt"});
}

TEST(UnsafeZip, symlink_entry_is_refused) {
  const auto dir = viscera::testing::scratch_dir();
  write_crafted_zip(dir / "link.vscz", "manifest.json", true);
  expect_error<InputError>([&] { read_package(dir / "link.vscz"); },
                           {"link.vscz", "symbolic link"});
}

TEST(UnsafeZip, entry_over_the_size_limit_is_refused_before_extraction) {
  const auto dir = viscera::testing::scratch_dir();
  write_crafted_zip(dir / "big.vscz", "manifest.json", false);
  expect_error<InputError>(
      [&] {
        checked_zip_entries(dir / "big.vscz", {4, 1000});
      },
      {"big.vscz", "over the limit"});
  expect_error<InputError>(
      [&] {
        checked_zip_entries(dir / "big.vscz", {1000, 4});
      },
      {"big.vscz", "more than the limit"});
}

TEST(PackageWrite, failed_write_leaves_nothing_behind) {
  const auto dir = viscera::testing::scratch_dir();
  Scenario scenario = viscera::testing::full_scenario();
  scenario.objects[0].material = "no-such-material";  // inconsistent: refused before renaming
  EXPECT_THROW(write_package(scenario, dir / "bad.vscene"), ValidationError);
  EXPECT_THROW(write_package(scenario, dir / "bad.vscz"), ValidationError);
  EXPECT_TRUE(entries_of(dir).empty()) << entries_of(dir).front();
}

TEST(PackageWrite, failed_rewrite_keeps_the_old_package_intact) {
  const auto dir = viscera::testing::scratch_dir();
  const Scenario good = viscera::testing::full_scenario();
  write_package(good, dir / "p.vscene");
  const std::string before = read_text(dir / "p.vscene" / "manifest.json");
  Scenario bad = good;
  bad.objects[0].body.tets[0] = {0, 0, 0, 0};  // degenerate tet
  EXPECT_THROW(write_package(bad, dir / "p.vscene"), InputError);
  EXPECT_EQ(read_text(dir / "p.vscene" / "manifest.json"), before);
  EXPECT_EQ(entries_of(dir), std::vector<std::string>{"p.vscene"});
  EXPECT_NO_THROW(read_package(dir / "p.vscene"));
}

TEST(PackageWrite, unwritable_destination_is_an_output_error) {
  const auto dir = viscera::testing::scratch_dir();
  write_text(dir / "a-file", "x");
  EXPECT_THROW(write_package(viscera::testing::full_scenario(), dir / "a-file" / "p.vscene"),
               OutputError);
}

TEST(PackagePack, pack_unpack_and_summary_agree) {
  const auto dir = viscera::testing::scratch_dir();
  write_package(viscera::testing::full_scenario(), dir / "p.vscene");
  pack_package(dir / "p.vscene", dir / "p.vscz");
  unpack_package(dir / "p.vscz", dir / "q.vscene");
  EXPECT_EQ(read_text(dir / "p.vscene" / "manifest.json"),
            read_text(dir / "q.vscene" / "manifest.json"));
  const PackageSummary summary = summarize_package(dir / "p.vscz");
  EXPECT_EQ(summary.format, kPackageFormat);
  EXPECT_EQ(summary.version, kPackageVersion);
  EXPECT_EQ(summary.object_count, 2);
  EXPECT_EQ(summary.body_tets, 10);
  EXPECT_EQ(summary.template_name, "hand-made");
  EXPECT_EQ(summary.seed, 99u);
}

TEST(ScenarioJson, round_trips_without_meshes_and_names_bad_members) {
  const Scenario original = viscera::testing::full_scenario();
  const nlohmann::json json = scenario_to_json(original);
  EXPECT_EQ(json["objects"][0]["surface"], "objects/uterus/surface.vtp");
  const Scenario back = scenario_from_json(json, "m.json");
  EXPECT_EQ(back.materials, original.materials);
  EXPECT_EQ(back.active_deformations, original.active_deformations);
  nlohmann::json broken = json;
  broken["objects"][1]["body_kind"] = "jelly";
  expect_error<ValidationError>([&] { scenario_from_json(broken, "m.json"); },
                                {"m.json", "/scenario/objects/1/body_kind"});
}

}  // namespace
}  // namespace viscera::core
