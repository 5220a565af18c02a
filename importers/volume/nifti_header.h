#pragma once
/// The first fields of a NIfTI-1, NIfTI-2 or Analyze 7.5 header, checked before VTK's NIfTI
/// reader sees the file. On a damaged header VTK 9.1's reader does not answer the same way twice:
/// the volume_nifti fuzz target's 384-byte files (a big-endian header whose datatype is 0x8001)
/// were refused as "Unrecognized NIFTI data type: 384" in five runs of twelve and let through in
/// the others, to an unsupported scalar type whose array asked for gigabytes. Checked here, the
/// same file is refused with the same sentence every time. Internal to viscera_importers.
///
/// Layout (NIfTI-1 and Analyze 7.5: nifti1.h, 348 bytes; NIfTI-2: nifti2.h, 540 bytes): the
/// header size sizeof_hdr (int32 at byte 0) is 348 or 540 in the file's byte order, which it
/// also tells; the datatype code and bits per voxel (int16) are at bytes 70 and 72 (NIfTI-1,
/// Analyze) or 12 and 14 (NIfTI-2). A .gz file is read through zlib.

#include <filesystem>

namespace viscera::importers::detail {

/// Throws core::InputError naming the file and the field when the header is cut short, its
/// size field is neither 348 nor 540 in either byte order, its datatype is not one VTK reads
/// (unsigned and signed 8 to 64-bit integers, 32 and 64-bit floats, RGB24, RGBA32, complex64
/// and complex128), or its bits per voxel differ from what that datatype holds.
void check_nifti_header(const std::filesystem::path& path);

}  // namespace viscera::importers::detail
