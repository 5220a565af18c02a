#pragma once
/// Shared steps of the volume readers: the memory budget check made from a header before any
/// allocation, copying VTK voxels into an ImageVolume, and setting geometry from a voxel-to-
/// world affine given in millimetres (converted to metres, RAS converted to LPS).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image/image_volume.h"
#include "importers/volume/volume_reader.h"

class vtkImageData;
class vtkImageReader2;

namespace viscera::importers::detail {

/// The bytes dims × components × bytes_per_component of the voxels a header declares. Throws
/// core::InputError naming `file` when dims are not positive or the bytes exceed
/// options.max_bytes ("header claims 100000×…").
std::uint64_t check_voxel_budget(const std::array<std::int64_t, 3>& dims, std::int64_t components,
                                 std::int64_t bytes_per_component, const VolumeReadOptions& options,
                                 const std::string& file);

/// Runs UpdateInformation() on `reader` (first in a guard's child) and checks its whole
/// extent, component count and scalar size against the budget; returns the declared voxel
/// bytes. Throws core::InputError naming `file` if the header cannot be read.
std::uint64_t check_reader_budget(vtkImageReader2& reader, const VolumeReadOptions& options,
                                  const std::string& file);

/// Copies the voxels of `image` (dims and values only; geometry is the caller's). Types with
/// no ImageVolume twin are widened (int8 → int16, uint32/int64 → float64); 3 or 4 components
/// become luminance (Rec. 601 weights), any other count keeps the first component and adds a
/// note. Throws core::InputError naming `file` if the image holds no voxels.
core::ImageVolume volume_from_vtk_image(vtkImageData& image, const std::string& file,
                                        std::vector<std::string>& notes);

/// Sets spacing, direction and origin from an affine in millimetres: columns of `axes` are the
/// world steps of +i, +j, +k, `origin` the world centre of voxel (0,0,0). With `ras`, x and y
/// are negated (RAS → LPS). Results in metres. Throws core::InputError naming `file` when an
/// axis has zero or non-finite length or the axes are not independent.
void set_geometry_mm(core::ImageVolume& volume, const core::Mat3& axes, const core::Vec3& origin,
                     bool ras, const std::string& file);

/// value ← slope·value + intercept (no-op for slope 1, intercept 0, or slope 0 which files use
/// for "no scaling"). Integral slope and intercept keep an integer type wide enough for the
/// result (int16, then int32; so CT stays in whole Hounsfield units); otherwise float32.
void apply_rescale(core::ImageVolume& volume, double slope, double intercept);

/// Throws core::InputError naming `file` if any voxel is NaN or infinite.
void check_finite(const core::ImageVolume& volume, const std::string& file);

}  // namespace viscera::importers::detail
