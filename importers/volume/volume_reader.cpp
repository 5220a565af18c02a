#include "importers/volume/volume_reader.h"

#include <algorithm>
#include <array>
#include <fstream>

#include "core/error.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/volume_geometry.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// The first `count` bytes of a file (fewer if it is shorter).
std::string head_bytes(const fs::path& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

using Reader = LoadedVolume (*)(const fs::path&, const VolumeReadOptions&);

/// The reader for a file, by extension first and then by its magic bytes.
Reader reader_for(const fs::path& path) {
  const std::string name = lower(path.filename().string());
  const std::array<std::pair<const char*, Reader>, 14> by_suffix{{
      {".nii", detail::read_nifti},
      {".nii.gz", detail::read_nifti},
      {".hdr", detail::read_nifti},
      {".img", detail::read_nifti},
      {".img.gz", detail::read_nifti},
      {".mhd", detail::read_metaimage},
      {".mha", detail::read_metaimage},
      {".nrrd", detail::read_nrrd},
      {".nhdr", detail::read_nrrd},
      {".vti", detail::read_vti},
      {".inr", detail::read_inr},
      {".inr.gz", detail::read_inr},
      {".mnc", detail::read_minc},
      {".dcm", detail::read_dicom},
  }};
  for (const auto& [suffix, reader] : by_suffix) {
    if (ends_with(name, suffix)) return reader;
  }
  if (ends_with(name, ".ima") || detail::has_dicom_magic(path)) return detail::read_dicom;
  const std::string head = head_bytes(path, 352);
  if (head.size() >= 348 && (head.compare(344, 4, std::string("n+1\0", 4)) == 0)) {
    return detail::read_nifti;
  }
  if (head.rfind("#INRIMAGE-4#{", 0) == 0) return detail::read_inr;
  if (head.rfind("NRRD000", 0) == 0) return detail::read_nrrd;
  return nullptr;
}

}  // namespace

std::vector<std::string> volume_formats() {
  return {"DICOM folder or file (.dcm, .ima, no extension)",
          "NIfTI (.nii, .nii.gz, .hdr/.img)",
          "MetaImage (.mhd, .mha)",
          "NRRD (.nrrd, .nhdr)",
          "VTK image (.vti)",
          "INRIMAGE (.inr, .inr.gz)",
          "MINC (.mnc)"};
}

LoadedVolume read_volume(const fs::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  std::error_code error;
  const auto status = fs::status(path, error);
  if (error || !fs::exists(status))
    throw core::InputError("no such file or folder", {file, "", ""});
  if (fs::is_directory(status)) return detail::read_dicom(path, options);
  if (!fs::is_regular_file(status)) throw core::InputError("not a regular file", {file, "", ""});
  if (fs::file_size(path) == 0) throw core::InputError("file is empty", {file, "", ""});
  const Reader reader = reader_for(path);
  if (reader == nullptr) {
    std::string known;
    for (const auto& format : volume_formats())
      known += (known.empty() ? "" : "; ") + format;
    throw core::InputError("not an image volume format Viscera reads (" + known + ")",
                           {file, "", ""});
  }
  LoadedVolume loaded;
  try {
    loaded = reader(path, options);
  } catch (const core::Error&) {
    throw;
  } catch (const std::exception& e) {
    // A library's own exception on a damaged file (vtkmetaio's std::length_error on a header
    // field, found by the volume_metaimage fuzz target) is an input error like any other.
    throw core::InputError(std::string("the file cannot be read: ") + e.what(), {file, "", ""});
  }
  detail::check_finite(loaded.volume, file);
  return loaded;
}

}  // namespace viscera::importers
