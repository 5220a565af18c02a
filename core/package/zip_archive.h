#pragma once
/// Zip archives of package folders (libzip), written byte-for-byte reproducibly and read with
/// the safety checks of DESIGN.md §4.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace viscera::core {

/// Writes every regular file under `folder` into the zip `archive`, sorted by path, deflated,
/// with a fixed time stamp and permissions so identical folders give identical archives.
/// Throws OutputError naming the archive.
void zip_folder(const std::filesystem::path& folder, const std::filesystem::path& archive);

/// Limits applied when reading an archive.
struct ZipLimits {
  std::uint64_t max_entry_bytes;  ///< uncompressed size of one entry
  std::uint64_t max_total_bytes;  ///< uncompressed size of all entries
};

/// Names of the entries of `archive` after the safety checks: no absolute paths, no ".."
/// components, no symbolic links, no duplicate names, no entry or total over the limits.
/// Throws InputError naming the archive and the offending entry.
std::vector<std::string> checked_zip_entries(const std::filesystem::path& archive,
                                             const ZipLimits& limits);

/// The bytes of one entry, after checked_zip_entries(); throws InputError naming the archive
/// when the entry is missing or corrupt.
std::string read_zip_entry(const std::filesystem::path& archive, const std::string& name,
                           const ZipLimits& limits);

/// Extracts `archive` into the existing empty folder `destination` after checked_zip_entries().
/// Throws InputError naming the archive and entry, OutputError naming the destination.
void unzip_to_folder(const std::filesystem::path& archive, const std::filesystem::path& destination,
                     const ZipLimits& limits);

}  // namespace viscera::core
