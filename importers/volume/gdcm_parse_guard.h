#pragma once
/// GDCM 3.0 as Debian builds it keeps its assertions: a damaged data element (one flipped byte
/// that turns the VR "UI" of a file meta element into "UK" is enough) makes it abort() the
/// process inside ReadExplicitDataElement/ReadImplicitDataElement, and a damaged spacing element
/// makes it assert in ImageHelper::GetSpacingValue while gdcm::ImageReader interprets a parsed
/// file. A clinician's folder of odd files must not take the studio down, so every DICOM file is
/// first parsed by GDCM and then read by its image reader in a forked child process, as the
/// parent will read it: a file that kills the child, or whose read takes longer than
/// core::kGuardSeconds (twice, core::kGuardAttempts), is reported with the stage it failed in,
/// and that stage never runs in this process. Pixel decoding (the codecs)
/// stays in the parent: it needs memory the child's limit cannot foresee from the file's size,
/// and fuzzing has found no codec crash. Internal to viscera_importers.
///
/// Cost: one extra parse and image read of each file (its data elements and image attributes, no
/// pixel decoding) in one child process per call (plus one more after each aborted file); the
/// parent's read then hits the page cache.

#include <filesystem>
#include <vector>

namespace viscera::importers::detail {

/// What GDCM survived of one file in the guard's child.
struct GdcmGuardResult {
  bool parses = true;       ///< gdcm::Reader parsed its data elements without aborting
  bool image_reads = true;  ///< and gdcm::ImageReader interpreted its image without aborting
};

/// For each of `files`, which of GDCM's two reads survive it (each may still refuse the file
/// cleanly, which the normal read reports). The parse comes first: a file whose parse aborts has
/// no image read either. Throws core::Error when no child process can be started.
std::vector<GdcmGuardResult> gdcm_reads_without_abort(
    const std::vector<std::filesystem::path>& files);

/// The reason given for a file whose read aborted GDCM.
inline constexpr const char* kGdcmAbortReason =
    "damaged DICOM data elements (GDCM aborts or hangs while reading them)";

}  // namespace viscera::importers::detail
