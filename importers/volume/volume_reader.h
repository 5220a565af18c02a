#pragma once
/// Image volumes from a patient's scan: one entry point that dispatches on the file or folder
/// (seed 001 §3.3: image data as the modelling aid; seed 003 §II: geometrically accurate models
/// are reconstructed from sliced data).
///
// clang-format off
/// | input                    | reader (file)                                         | geometry it carries                                                       |
/// |--------------------------|-------------------------------------------------------|---------------------------------------------------------------------------|
/// | folder of DICOM files    | GDCM ImageReader (dicom_series.cpp, dicom_reader.cpp) | Pixel Spacing, Image Position/Orientation (Patient); slices ordered along their normal, evenly spaced; several series: the largest read, the others listed; Rescale Slope/Intercept per slice |
/// | .dcm, .ima, DICM file    | same                                                  | same, one file (several frames give a volume)                             |
/// | .nii .nii.gz .hdr/.img   | vtkNIFTIImageReader (nifti_reader.cpp)                | pixdim, sform if sform_code > 0 else qform (qfac), xyzt_units, scl_slope/inter; 4D: first volume |
/// | .mhd .mha                | vtkMetaImageReader (metaimage_reader.cpp)             | ElementSpacing, Offset, TransformMatrix (read from the header text)       |
/// | .nrrd .nhdr              | read here, raw or gzip (nrrd_reader.cpp)              | space directions, space origin, space (RAS/LPS); else spacings            |
/// | .vti                     | VTK XML (vti_reader.cpp)                              | spacing, origin, direction matrix, already in metres                      |
/// | .inr .inr.gz             | CGAL Image_3 (inr_reader.cpp)                         | VX/VY/VZ spacing, TX/TY/TZ origin (mm); no orientation                     |
/// | .mnc                     | vtkMINCImageReader (minc_reader.cpp)                  | MINC 1: step, start, direction cosines; real values rescaled; MINC 2 (HDF5) refused |
// clang-format on
///
/// Results are in metres in patient LPS coordinates (DICOM's: +x left, +y posterior, +z head):
/// millimetre files are scaled by 0.001, RAS files (NIfTI, MINC, NRRD "RAS") have x and y
/// negated. Multi-component voxels (RGB) become luminance. Header sizes are checked against
/// VolumeReadOptions::max_bytes before any voxel is allocated; truncated files and NaN or
/// infinite voxels are refused.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/image/image_volume.h"

namespace viscera::importers {

/// Limits and choices for reading a volume.
struct VolumeReadOptions {
  /// Largest voxel buffer a header may ask for, in bytes (default 4 GiB); larger is refused
  /// with core::InputError before allocation.
  std::uint64_t max_bytes = 4ULL << 30;
};

/// One DICOM series found in a folder.
struct DicomSeriesSummary {
  std::string uid;
  std::string description;
  std::string modality;
  int files = 0;
};

/// A file of a DICOM folder that was not read, and why.
struct SkippedFile {
  std::filesystem::path file;
  std::string reason;
};

/// A volume read from disk and where it came from.
struct LoadedVolume {
  core::ImageVolume volume;
  std::string format;                            ///< "DICOM", "NIfTI", "MetaImage", …
  std::vector<std::filesystem::path> files;      ///< the files whose voxels were read
  std::vector<DicomSeriesSummary> other_series;  ///< DICOM series in the folder not read
  std::vector<std::string> notes;                ///< e.g. "first of 4 time points read"
  std::vector<SkippedFile> skipped_files;        ///< DICOM files of a folder left out, with why
};

/// Names of the formats read_volume() understands, for help texts.
std::vector<std::string> volume_formats();

/// Reads a volume file or DICOM folder. Throws core::InputError naming the file and the reason
/// when it is missing, unreadable, truncated, of an unknown format, or claims more voxels than
/// options.max_bytes allows.
LoadedVolume read_volume(const std::filesystem::path& path, const VolumeReadOptions& options = {});

}  // namespace viscera::importers
