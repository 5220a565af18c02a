#pragma once
/// The value lengths a DICOM file's data elements declare, checked against the file before GDCM
/// reads it. GDCM 3.0 allocates and zero-fills a value of the declared length before reading
/// it: 41 stray bytes after the pixel data of a 9.7 KB MR slice, read as an element of 3.0 GB,
/// took 3.4 GB and 22 s in the fuzz build (3.0 GB and 4 to 7 s in the normal build, once in the
/// parse guard's child and again in the reader): the volume_dicom_file fuzz target's finding,
/// tests/fuzz/regressions/volume_dicom_file/. Internal to viscera_importers.
///
/// The walk follows DICOM PS3.5 §7 and PS3.10 §7: after the 128-byte preamble and "DICM", the
/// file meta group in explicit VR little endian, then the data set in the transfer syntax the
/// group names (implicit or explicit VR, little or big endian). Values are not read, only tags
/// and lengths; sequences and items of undefined length, and encapsulated pixel data fragments,
/// are walked into. An element whose VR is not a VR is taken as implicit VR there, as GDCM does,
/// in the file meta group too: a 253-byte file whose first meta element (0002,5800) has the VR
/// bytes CD 0C made GDCM read its next four bytes as a length and ask for 3.76 GB (the
/// volume_dicom_file finding of stop 18, tests/fuzz/regressions/volume_dicom_file/).
/// Pixel data of undefined length is refused in a native (uncompressed) transfer syntax, and
/// encapsulated pixel data must hold fragment items up to its delimiter (PS3.5 §A.4): GDCM
/// would read the pixels on as elements (the fuzz finding of stop 16, a 12.9 KB big-endian slice
/// whose pixels it read as a 4 GB element).
/// Where the structure is not one the walk knows (no preamble, no transfer syntax, deflated
/// data, a delimiter out of place), it stops and leaves the file to GDCM and its parse guard.

#include <filesystem>
#include <optional>
#include <string>

namespace viscera::importers::detail {

/// Why the file cannot hold what its elements declare ("pixel data is truncated: …" for Pixel
/// Data, "damaged DICOM data element (GGGG,EEEE) at byte N: …" for any other element or item
/// whose value would run past the end of the file), or nothing when every length fits.
std::optional<std::string> dicom_length_problem(const std::filesystem::path& path);

}  // namespace viscera::importers::detail
