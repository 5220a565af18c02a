#pragma once
/// Some readers of Debian's VTK 9.1 crash on damaged headers instead of reporting an error: the
/// NIfTI reader takes a SIGBUS in RequestInformation on a few flipped bytes (volume_nifti fuzz
/// target). The header stage of every VTK volume reader therefore runs first in a forked child,
/// as GDCM's parse does (gdcm_parse_guard.h): a header that kills the child is refused, never
/// read in this process. Internal to viscera_importers.
///
/// Cost: one fork and one header read per volume (no voxels); the parent's read then hits the
/// page cache.

#include <functional>

namespace viscera::importers::detail {

/// Runs `attempt` in a forked child process with stderr silenced. True when the child finished
/// (returned or threw: a clean refusal the caller will meet again), false when a signal ended it
/// (a crash or an abort). Throws core::Error when no child process can be started.
bool survives_in_child(const std::function<void()>& attempt);

}  // namespace viscera::importers::detail
