#pragma once
/// The per-format readers behind read_volume() (volume_reader.h has the table of what each
/// carries). Internal to viscera_importers.

#include <filesystem>

#include "importers/volume/volume_reader.h"

namespace viscera::importers::detail {

LoadedVolume read_dicom(const std::filesystem::path& path, const VolumeReadOptions& options);
LoadedVolume read_nifti(const std::filesystem::path& path, const VolumeReadOptions& options);
LoadedVolume read_metaimage(const std::filesystem::path& path, const VolumeReadOptions& options);
LoadedVolume read_nrrd(const std::filesystem::path& path, const VolumeReadOptions& options);
LoadedVolume read_vti(const std::filesystem::path& path, const VolumeReadOptions& options);
LoadedVolume read_inr(const std::filesystem::path& path, const VolumeReadOptions& options);
LoadedVolume read_minc(const std::filesystem::path& path, const VolumeReadOptions& options);

/// True when the file starts with a DICOM preamble ("DICM" at byte 128).
bool has_dicom_magic(const std::filesystem::path& path);

}  // namespace viscera::importers::detail
