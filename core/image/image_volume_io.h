#pragma once
/// Image volumes and label maps as VTK XML image data (.vti), with their full geometry:
/// VTK 9.1's XML image format keeps origin, spacing and the direction matrix. Label names
/// travel as field data ("label_names": one "label=name" string per label).

#include <filesystem>

#include "core/image/image_volume.h"

class vtkImageData;

namespace viscera::core {

/// Copies `volume` into `image`: dimensions, spacing, origin, direction matrix and one scalar
/// component named "scalars" (for views and filters that take VTK images).
void volume_to_image_data(const ImageVolume& volume, vtkImageData& image);

/// Writes `volume` to `path` (uncompressed, appended raw: same volume → same bytes) through a
/// temporary sibling. Throws OutputError naming the file.
void write_volume_vti(const ImageVolume& volume, const std::filesystem::path& path);

/// Reads a one-component .vti; throws InputError naming the file when it is unreadable, has
/// several components or an unsupported scalar type.
ImageVolume read_volume_vti(const std::filesystem::path& path);

/// Writes a label map (UInt16 labels and their names).
void write_label_map_vti(const LabelMap& labels, const std::filesystem::path& path);

/// Reads a label map; throws InputError when the file's scalars are not unsigned 16-bit.
LabelMap read_label_map_vti(const std::filesystem::path& path);

}  // namespace viscera::core
