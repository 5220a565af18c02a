#pragma once
/// Real image files of Debian packages (python3-pydicom, python3-nibabel, libcgal-demo) and what
/// their headers say, read by volume_headers.py through pydicom and nibabel, not by Viscera.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "importers/volume/volume_reader.h"
#include "tests/support/test_paths.h"

namespace viscera::testing {

/// pydicom's test file `name` (e.g. "CT_small.dcm") or folder.
std::filesystem::path pydicom_file(const std::string& name);

/// nibabel's test data file `name` (e.g. "anatomical.nii").
std::filesystem::path nibabel_file(const std::string& name);

/// The header facts of every real file (volume_headers.py run with /usr/bin/python3).
nlohmann::json real_volume_headers(const std::filesystem::path& scratch);

/// A copy of `source` in `dir` named `name`.
std::filesystem::path copy_to(const std::filesystem::path& source, const std::filesystem::path& dir,
                              const std::string& name);

/// What read_volume says of `path`: the InputError's message, or "no error".
std::string volume_read_error(const std::filesystem::path& path,
                              const importers::VolumeReadOptions& options = {});

/// True when `text` contains `part`.
inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace viscera::testing
