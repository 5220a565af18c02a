#include "core/library/asset_entry_file.h"

#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_numbers.h"
#include "core/package/zip_archive.h"
#include "core/sha256.h"

namespace viscera::core {
namespace {

/// An entry file holds one asset; its payload may be a whole package.
constexpr ZipLimits kEntryLimits{2ULL << 30, 4ULL << 30};

void write_file(const std::string& bytes, const std::filesystem::path& path,
                const std::filesystem::path& shown) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw OutputError("cannot write the entry file", {shown.string(), "", ""});
}

}  // namespace

void export_asset_entry(const AssetEntry& entry, const std::filesystem::path& file) {
  check_asset_entry(entry);
  const AssetSummary& s = entry.summary;
  const std::string payload_name = "payload." + s.payload_format;
  nlohmann::json json = {{"format", kAssetEntryFormat},
                         {"version", kAssetEntryFormatVersion},
                         {"name", s.name},
                         {"type", to_string(s.type)},
                         {"entry_version", s.version},
                         {"tags", s.tags},
                         {"provenance", s.provenance},
                         {"payload", payload_name},
                         {"payload_format", s.payload_format},
                         {"payload_sha256", sha256_hex(entry.payload)},
                         {"thumbnail", entry.thumbnail.empty() ? nlohmann::json(nullptr)
                                                               : nlohmann::json("thumbnail.png")}};
  const std::filesystem::path target = std::filesystem::absolute(file);
  const std::string stem =
      "." + target.filename().string() + ".partial-" + std::to_string(::getpid());
  const std::filesystem::path folder = target.parent_path() / (stem + "-dir");
  const std::filesystem::path archive = target.parent_path() / (stem + ".zip");
  std::error_code ec;
  std::filesystem::remove_all(folder, ec);
  try {
    if (!std::filesystem::create_directories(folder, ec) || ec)
      throw OutputError("cannot create a temporary folder beside the entry file",
                        {file.string(), "", ""});
    write_file(json.dump(2) + "\n", folder / "entry.json", file);
    write_file(entry.payload, folder / payload_name, file);
    if (!entry.thumbnail.empty()) write_file(entry.thumbnail, folder / "thumbnail.png", file);
    zip_folder(folder, archive);
    std::filesystem::rename(archive, target, ec);
    if (ec)
      throw OutputError("cannot move the entry file into place: " + ec.message(),
                        {file.string(), "", ""});
  } catch (...) {
    std::filesystem::remove_all(folder, ec);
    std::filesystem::remove(archive, ec);
    throw;
  }
  std::filesystem::remove_all(folder, ec);
}

AssetEntry import_asset_entry(const std::filesystem::path& file) {
  const std::string where = file.string();
  checked_zip_entries(file, kEntryLimits);
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(read_zip_entry(file, "entry.json", kEntryLimits));
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(std::string("entry.json is not JSON: ") + e.what(), {where, "", ""});
  }
  AssetEntry entry;
  AssetSummary& s = entry.summary;
  std::string pointer;
  try {
    pointer = "/format";
    if (json.at("format").get<std::string>() != kAssetEntryFormat)
      throw InputError("not a Viscera library entry", {where, pointer, ""});
    pointer = "/version";
    if (whole_number<int>(json.at("version"), where, pointer) > kAssetEntryFormatVersion)
      throw UnsupportedVersionError(
          "entry format version " + json.at("version").dump() + " is newer than this build reads",
          {where, pointer, ""});
    pointer = "/name";
    s.name = json.at("name").get<std::string>();
    pointer = "/type";
    s.type = asset_type_from_string(json.at("type").get<std::string>());
    pointer = "/entry_version";
    s.version = whole_number<int>(json.at("entry_version"), where, pointer);
    pointer = "/tags";
    s.tags = json.at("tags").get<std::vector<std::string>>();
    pointer = "/provenance";
    s.provenance = json.at("provenance").get<std::string>();
    pointer = "/payload_format";
    s.payload_format = json.at("payload_format").get<std::string>();
    pointer = "/payload_sha256";
    s.payload_sha256 = json.at("payload_sha256").get<std::string>();
    pointer = "/payload";
    entry.payload = read_zip_entry(file, json.at("payload").get<std::string>(), kEntryLimits);
    pointer = "/thumbnail";
    if (!json.at("thumbnail").is_null())
      entry.thumbnail = read_zip_entry(file, json.at("thumbnail").get<std::string>(), kEntryLimits);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("entry.json: ") + e.what(), {where, pointer, ""});
  } catch (const UsageError& e) {
    throw InputError("entry.json: " + e.reason(), {where, pointer, ""});
  }
  s.payload_bytes = entry.payload.size();
  s.has_thumbnail = !entry.thumbnail.empty();
  if (sha256_hex(entry.payload) != s.payload_sha256)
    throw ValidationError("the payload does not match its checksum",
                          {where, "/payload_sha256", ""});
  try {
    check_asset_entry(entry);
  } catch (const UsageError& e) {
    throw InputError("entry.json: " + e.reason(), {where, "", s.name});
  }
  return entry;
}

}  // namespace viscera::core
