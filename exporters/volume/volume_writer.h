#pragma once
/// Image volumes to disk, by extension (`viscera volume convert`):
///
// clang-format off
/// | extension     | writer                                                   | geometry written                                  |
/// |---------------|----------------------------------------------------------|---------------------------------------------------|
/// | .vti          | VTK XML (core/image/image_volume_io.h)                   | origin, spacing, direction in metres              |
/// | .nii, .nii.gz | vtkNIFTIImageWriter                                      | pixdim, qform and sform, RAS, mm                  |
/// | .mha          | written here: MetaImage text header + raw little-endian  | ElementSpacing, Offset, TransformMatrix (LPS, mm) |
// clang-format on
///
/// Every writer goes through exporters::StagedOutput: a failure leaves no partial file and an
/// older file of the same name stays until the new one is complete.

#include <filesystem>
#include <string>
#include <vector>

#include "core/image/image_volume.h"

namespace viscera::exporters {

/// The extensions write_volume() understands.
std::vector<std::string> volume_writer_extensions();

/// Writes `volume` to `path`, the format chosen by its extension. Throws core::UsageError for an
/// unknown extension, core::OutputError naming the file when writing fails.
void write_volume(const core::ImageVolume& volume, const std::filesystem::path& path);

}  // namespace viscera::exporters
