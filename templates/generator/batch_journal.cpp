#include "templates/generator/batch_journal.h"

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/package/package_manifest.h"
#include "core/package/scenario_package.h"
#include "core/sha256.h"
#include "templates/generator/batch_index.h"

namespace viscera::templates {
namespace fs = std::filesystem;
namespace {

constexpr const char* kHeaderFile = "batch.json";

std::optional<nlohmann::json> read_json_if_any(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // a journal entry cut short: the patient is generated again
  }
}

std::string entry_name(std::uint64_t k) {
  return "patient-" + std::to_string(k) + ".json";
}

}  // namespace

BatchJournal::BatchJournal(const fs::path& folder, const nlohmann::json& header)
    : folder_(folder), journal_(folder / kJournalFolder) {
  std::error_code error;
  fs::create_directories(journal_, error);
  if (error)
    throw core::OutputError("cannot create the batch journal", {journal_.string(), "", ""});
  const fs::path header_file = journal_ / kHeaderFile;
  if (const auto existing = read_json_if_any(header_file)) {
    if (*existing != header) {
      throw core::UsageError(
          "the folder holds an unfinished batch generated with other arguments (template, seed, "
          "count or rules); restart it with the same arguments or use another folder",
          {folder.string(), "", ""});
    }
    return;
  }
  write_json_atomically(header, header_file);
}

std::optional<nlohmann::json> BatchJournal::kept_record(std::uint64_t k,
                                                        const std::string& package) const {
  const auto entry = read_json_if_any(journal_ / entry_name(k));
  if (!entry || !entry->is_object() || !entry->contains("record") ||
      !entry->contains("manifest_sha256"))
    return std::nullopt;
  const fs::path path = folder_ / package;
  const fs::path manifest = path / core::kManifestFile;
  std::error_code error;
  if (!fs::is_regular_file(manifest, error)) return std::nullopt;
  try {
    if (core::sha256_file(manifest) != entry->at("manifest_sha256").get<std::string>())
      return std::nullopt;
    (void)core::read_package(path);  // every file against its checksum in the manifest
  } catch (const core::Error&) {
    return std::nullopt;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  const nlohmann::json& record = entry->at("record");
  if (!record.is_object() || record.value("index", k + 1) != k ||
      record.value("package", std::string()) != package)
    return std::nullopt;
  return record;
}

void BatchJournal::record(std::uint64_t k, const nlohmann::json& patient_record) const {
  const fs::path manifest =
      folder_ / patient_record.at("package").get<std::string>() / core::kManifestFile;
  write_json_atomically(
      {{"record", patient_record}, {"manifest_sha256", core::sha256_file(manifest)}},
      journal_ / entry_name(k));
}

void BatchJournal::remove_stale_staging(const std::string& package) const {
  const std::string prefix = "." + package + ".tmp-";
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder_, error)) {
    if (entry.path().filename().string().rfind(prefix, 0) == 0) fs::remove_all(entry.path(), error);
  }
}

void BatchJournal::remove(const fs::path& folder) {
  std::error_code error;
  fs::remove_all(folder / kJournalFolder, error);
}

}  // namespace viscera::templates
