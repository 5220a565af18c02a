#pragma once
/// The header of a netCDF classic file (CDF-1, CDF-2 64-bit offset, CDF-5; the file format of
/// MINC 1), walked before VTK's MINC reader opens the file. The netCDF library allocates and
/// fills whatever an attribute's count declares while it reads the header: a 14 KB file whose
/// attribute claimed 1.6 billion 4-byte values took 6.5 GB and 20 s before it was refused (the
/// volume_minc fuzz target's finding, tests/fuzz/regressions/volume_minc/). Internal to
/// viscera_importers.
///
/// Layout (netCDF "File Format Specification", big-endian): magic "CDF" and a version byte, the
/// record count, then the dimension, global attribute and variable lists, each a tag and an
/// element count; counts, lengths and sizes are 4 bytes (8 in CDF-5), data offsets 4 bytes in
/// CDF-1 and 8 in CDF-2 and CDF-5.

#include <filesystem>

namespace viscera::importers::detail {

/// Throws core::InputError naming the file and the byte offset when the header cannot be what
/// it declares: an unknown version or value type, a list, name or attribute value that would
/// run past the end of the file, a list tag out of place; or when the variable "image" (MINC's
/// voxels) declares more voxels than the file holds after the offset its data starts at.
void check_netcdf_header(const std::filesystem::path& path);

}  // namespace viscera::importers::detail
