#pragma once
/// DICOM headers without pixels: which files of a folder are images, how they group into series,
/// and the order and spacing of a series' slices along the normal of their planes. Internal to
/// viscera_importers (dicom_reader.cpp decodes the pixels).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "importers/volume/volume_reader.h"

namespace viscera::importers::detail {

/// What the header of one DICOM image file says (GDCM reads it up to the pixel data).
struct DicomHeader {
  std::filesystem::path file;
  std::string series_uid, description, modality;
  int rows = 0, columns = 0, frames = 1, samples = 1, bits_allocated = 0, instance = 0;
  bool has_position = false, has_orientation = false, has_pixel_spacing = false;
  double slope = 1.0, intercept = 0.0;  ///< Rescale Slope/Intercept (modality LUT)
  bool has_number_of_frames = false;
  core::Vec2 pixel_spacing = core::Vec2::Zero();  ///< Pixel Spacing (x, y) in mm, 0 if absent
  bool deflated = false;    ///< Deflated Explicit VR: offsets are not file offsets
  bool native = false;      ///< uncompressed pixel data: implicit or explicit VR, either byte order
  std::string photometric;  ///< Photometric Interpretation, e.g. "MONOCHROME2", "YBR_FULL_422"
  core::Vec3 position = core::Vec3::Zero();  ///< Image Position (Patient), mm
  core::Vec3 row_direction = core::Vec3::UnitX(), column_direction = core::Vec3::UnitY();
  bool image_reader_aborts = false;  ///< GDCM's image reader aborted on it in the guard's child
};

/// Why GDCM's image reader cannot read `header`'s file, or nothing: an RT Dose file without
/// Number of Frames (0028,0008), which GDCM 3.0 needs, or an image read that aborted in the
/// guard's child (gdcm_parse_guard.h).
std::optional<std::string> gdcm_cannot_read(const DicomHeader& header);

/// Reads the header of `file`; false (and no throw) when it is not a DICOM image.
bool read_dicom_header(const std::filesystem::path& file, DicomHeader& header);

/// The image files of `folder` and its sub-folders grouped by Series Instance UID, the series
/// with the most files first (ties by UID, so the choice is deterministic). Files with an element
/// length the file cannot hold (dicom_element_lengths.h), whose parse aborts GDCM, or images GDCM
/// cannot read (gdcm_cannot_read) are left out and listed in `skipped`. Throws
/// core::InputError naming the folder when it holds no DICOM image.
std::vector<std::vector<DicomHeader>> dicom_series_in(const std::filesystem::path& folder,
                                                      std::vector<SkippedFile>& skipped);

/// A summary of a series for LoadedVolume::other_series.
DicomSeriesSummary summarize(const std::vector<DicomHeader>& series);

/// The slices of one series ordered along the normal of their planes (row × column direction),
/// with the mean distance between neighbours in mm. Throws core::InputError naming `folder`
/// when slices lack a position or orientation, are not parallel, share a position, or are not
/// evenly spaced (gaps differing by more than 1 % of their mean).
struct StackedSlices {
  std::vector<DicomHeader> slices;
  double spacing_mm = 1.0;
};
StackedSlices stack_slices(std::vector<DicomHeader> series, const std::string& folder);

}  // namespace viscera::importers::detail
