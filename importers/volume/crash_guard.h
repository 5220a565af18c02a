#pragma once
/// Some readers of Debian's VTK 9.1 crash on damaged files instead of reporting an error (fuzz
/// findings): the NIfTI reader takes a SIGBUS in RequestInformation and a SEGV in RequestData,
/// the XML and legacy mesh readers a SEGV. So these reads run first in a forked child, as
/// GDCM's parse does (gdcm_parse_guard.h): a file that kills the child is refused, never read in
/// this process. Used for the header stage of every VTK volume reader, the whole NIfTI read and
/// the whole VTK mesh read. Internal to viscera_importers.
///
/// Cost: one fork and the guarded read done twice (the second from the page cache).

#include <functional>

namespace viscera::importers::detail {

/// Runs `attempt` in a forked child process with stderr silenced. True when the child finished
/// (returned or threw: a clean refusal the caller will meet again), false when a signal ended it
/// (a crash or an abort). Throws core::Error when no child process can be started.
bool survives_in_child(const std::function<void()>& attempt);

}  // namespace viscera::importers::detail
