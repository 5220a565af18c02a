#pragma once
/// One asset library entry as a file, for exchanging entries between libraries: a zip (written
/// reproducibly by core/package/zip_archive.h) of
///   entry.json         format "viscera-library-entry" version 1: name, type, version, tags,
///                      provenance, payload format and SHA-256
///   payload.<format>   the payload's bytes
///   thumbnail.png      the thumbnail, when the entry has one

#include <filesystem>

#include "core/library/asset_library.h"

namespace viscera::core {

inline constexpr const char* kAssetEntryFormat = "viscera-library-entry";
inline constexpr int kAssetEntryFormatVersion = 1;

/// Writes `entry` to `file` through a temporary sibling renamed into place; the same entry
/// gives the same bytes. Throws as check_asset_entry, OutputError naming the file.
void export_asset_entry(const AssetEntry& entry, const std::filesystem::path& file);

/// Reads a file written by export_asset_entry (summary.version as exported). Throws InputError
/// naming the file and the member for an unreadable or malformed archive,
/// UnsupportedVersionError for a newer format, ValidationError when the payload fails its
/// checksum.
AssetEntry import_asset_entry(const std::filesystem::path& file);

}  // namespace viscera::core
