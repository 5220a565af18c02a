#pragma once
/// GDCM 3.0 as Debian builds it keeps its assertions: a damaged data element (one flipped byte
/// that turns the VR "UI" of a file meta element into "UK" is enough) makes it abort() the
/// process inside ReadExplicitDataElement/ReadImplicitDataElement. A clinician's folder of odd
/// files must not take the studio down, so every DICOM file is first parsed by GDCM in a forked
/// child process: a file that kills the child, or whose parse takes longer than
/// core::kGuardSeconds (twice, core::kGuardAttempts), is reported, never read in this process.
/// Internal to viscera_importers.
///
/// Cost: one extra parse of each file's data elements (no pixel decoding) in one child process
/// per call (plus one more after each aborted file); the parent's read then hits the page cache.

#include <filesystem>
#include <vector>

namespace viscera::importers::detail {

/// For each of `files`, true when GDCM can parse it without aborting (it may still refuse it
/// cleanly, which the normal read reports), false when parsing it aborted or hung the child.
/// Throws core::Error when no child process can be started.
std::vector<bool> gdcm_parses_without_abort(const std::vector<std::filesystem::path>& files);

/// The reason given for a file whose parse aborted GDCM.
inline constexpr const char* kGdcmAbortReason =
    "damaged DICOM data element structure (GDCM aborts or hangs while parsing it)";

}  // namespace viscera::importers::detail
