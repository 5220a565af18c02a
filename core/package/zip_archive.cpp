#include "core/package/zip_archive.h"

#include <sys/stat.h>
#include <zip.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <set>

#include "core/error.h"

namespace viscera::core {
namespace {

/// 1980-01-01 00:00 local DOS time is the zip format's epoch; any fixed value makes archives
/// reproducible. 315532800 s is 1980-01-01 UTC.
constexpr time_t kFixedTimestamp = 315532800;
constexpr zip_uint32_t kRegularFileMode = 0100644;

struct ArchiveCloser {
  void operator()(zip_t* archive) const {
    if (archive != nullptr) zip_discard(archive);
  }
};
using ArchivePtr = std::unique_ptr<zip_t, ArchiveCloser>;

std::string libzip_error(zip_t* archive) {
  const char* text = zip_strerror(archive);
  return text != nullptr ? text : "unknown libzip error";
}

ArchivePtr open_for_reading(const std::filesystem::path& archive) {
  int error_code = 0;
  zip_t* handle = zip_open(archive.string().c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &error_code);
  if (handle == nullptr) {
    zip_error_t error;
    zip_error_init_with_code(&error, error_code);
    const std::string reason = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw InputError("not a readable zip archive (" + reason + ")", {archive.string(), "", ""});
  }
  return ArchivePtr(handle);
}

bool is_unsafe_path(const std::string& name) {
  if (name.empty() || name.front() == '/' || name.front() == '\\') return true;
  if (name.size() > 1 && name[1] == ':') return true;  // a drive letter
  if (name.find('\\') != std::string::npos) return true;
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    if (name.compare(start, end - start, "..") == 0 && end - start == 2) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace

void zip_folder(const std::filesystem::path& folder, const std::filesystem::path& archive) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) files.push_back(std::filesystem::relative(entry.path(), folder));
  }
  std::sort(files.begin(), files.end());

  int error_code = 0;
  zip_t* raw = zip_open(archive.string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error_code);
  if (raw == nullptr)
    throw OutputError("cannot create the zip archive", {archive.string(), "", ""});
  ArchivePtr handle(raw);
  for (const auto& relative : files) {
    const std::string name = relative.generic_string();
    zip_source_t* source = zip_source_file(raw, (folder / relative).string().c_str(), 0, -1);
    if (source == nullptr)
      throw OutputError("cannot read " + name + ": " + libzip_error(raw),
                        {archive.string(), "", ""});
    const zip_int64_t index =
        zip_file_add(raw, name.c_str(), source, ZIP_FL_ENC_UTF_8 | ZIP_FL_OVERWRITE);
    if (index < 0) {
      zip_source_free(source);
      throw OutputError("cannot add " + name + ": " + libzip_error(raw),
                        {archive.string(), "", ""});
    }
    const auto i = static_cast<zip_uint64_t>(index);
    if (zip_set_file_compression(raw, i, ZIP_CM_DEFLATE, 6) != 0 ||
        zip_file_set_mtime(raw, i, kFixedTimestamp, 0) != 0 ||
        zip_file_set_external_attributes(raw, i, 0, ZIP_OPSYS_UNIX, kRegularFileMode << 16) != 0) {
      throw OutputError("cannot set attributes of " + name + ": " + libzip_error(raw),
                        {archive.string(), "", ""});
    }
  }
  if (zip_close(raw) != 0)
    throw OutputError("cannot write the zip archive: " + libzip_error(raw),
                      {archive.string(), "", ""});
  (void)handle.release();  // zip_close freed it
}

std::vector<std::string> checked_zip_entries(const std::filesystem::path& archive,
                                             const ZipLimits& limits) {
  const ArchivePtr handle = open_for_reading(archive);
  const std::string file = archive.string();
  const zip_int64_t count = zip_get_num_entries(handle.get(), 0);
  std::vector<std::string> names;
  std::set<std::string> seen;
  std::uint64_t total = 0;
  for (zip_int64_t i = 0; i < count; ++i) {
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat_index(handle.get(), static_cast<zip_uint64_t>(i), 0, &stat) != 0 ||
        (stat.valid & ZIP_STAT_NAME) == 0) {
      throw InputError("entry " + std::to_string(i) + " cannot be read", {file, "", ""});
    }
    const std::string name = stat.name;
    if (is_unsafe_path(name)) {
      throw InputError(
          "entry \"" + name + "\" points outside the package (absolute path or \"..\"); refused",
          {file, "", name});
    }
    zip_uint8_t opsys = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(handle.get(), static_cast<zip_uint64_t>(i), 0, &opsys,
                                         &attributes) == 0 &&
        opsys == ZIP_OPSYS_UNIX && ((attributes >> 16) & S_IFMT) == S_IFLNK) {
      throw InputError("entry \"" + name + "\" is a symbolic link; refused", {file, "", name});
    }
    if (!seen.insert(name).second)
      throw InputError("entry \"" + name + "\" appears twice", {file, "", name});
    if ((stat.valid & ZIP_STAT_SIZE) != 0) {
      if (stat.size > limits.max_entry_bytes) {
        throw InputError("entry \"" + name + "\" unpacks to " + std::to_string(stat.size) +
                             " bytes, over the limit of " + std::to_string(limits.max_entry_bytes),
                         {file, "", name});
      }
      total += stat.size;
      if (total > limits.max_total_bytes) {
        throw InputError("archive unpacks to more than the limit of " +
                             std::to_string(limits.max_total_bytes) + " bytes",
                         {file, "", ""});
      }
    }
    names.push_back(name);
  }
  return names;
}

std::string read_zip_entry(const std::filesystem::path& archive, const std::string& name,
                           const ZipLimits& limits) {
  const auto names = checked_zip_entries(archive, limits);
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw InputError("archive has no entry \"" + name + "\"", {archive.string(), "", name});
  }
  const ArchivePtr handle = open_for_reading(archive);
  zip_file_t* entry = zip_fopen(handle.get(), name.c_str(), 0);
  if (entry == nullptr)
    throw InputError("entry \"" + name + "\" cannot be opened", {archive.string(), "", name});
  std::string bytes;
  std::vector<char> buffer(1 << 16);
  zip_int64_t got = 0;
  while ((got = zip_fread(entry, buffer.data(), buffer.size())) > 0) {
    bytes.append(buffer.data(), static_cast<std::size_t>(got));
    if (bytes.size() > limits.max_entry_bytes) break;
  }
  zip_fclose(entry);
  if (got < 0 || bytes.size() > limits.max_entry_bytes) {
    throw InputError("entry \"" + name + "\" is corrupt or too large",
                     {archive.string(), "", name});
  }
  return bytes;
}

void unzip_to_folder(const std::filesystem::path& archive, const std::filesystem::path& destination,
                     const ZipLimits& limits) {
  const std::vector<std::string> names = checked_zip_entries(archive, limits);
  const ArchivePtr handle = open_for_reading(archive);
  const std::string file = archive.string();
  std::vector<char> buffer(1 << 16);
  for (const auto& name : names) {
    const auto target = destination / std::filesystem::path(name);
    if (name.back() == '/') {
      std::filesystem::create_directories(target);
      continue;
    }
    std::filesystem::create_directories(target.parent_path());
    zip_file_t* entry = zip_fopen(handle.get(), name.c_str(), 0);
    if (entry == nullptr)
      throw InputError("entry \"" + name + "\" cannot be opened", {file, "", name});
    std::ofstream out(target, std::ios::binary);
    std::uint64_t written = 0;
    zip_int64_t got = 0;
    while ((got = zip_fread(entry, buffer.data(), buffer.size())) > 0) {
      written += static_cast<std::uint64_t>(got);
      // Sizes in the directory can lie; count what actually comes out.
      if (written > limits.max_entry_bytes) {
        zip_fclose(entry);
        throw InputError("entry \"" + name + "\" unpacks beyond the size limit", {file, "", name});
      }
      out.write(buffer.data(), got);
    }
    const bool read_failed = got < 0;
    zip_fclose(entry);
    if (read_failed) throw InputError("entry \"" + name + "\" is corrupt", {file, "", name});
    if (!out)
      throw OutputError("cannot write " + target.string(), {destination.string(), "", name});
  }
}

}  // namespace viscera::core
