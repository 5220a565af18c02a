#pragma once
/// Some readers of Debian's VTK 9.1 crash or hang on damaged files instead of reporting an error
/// (fuzz findings): the NIfTI reader takes a SIGBUS in RequestInformation and a SEGV in
/// RequestData, the XML and legacy mesh readers a SEGV, the MINC reader loops. So these reads run
/// first in a forked child, as GDCM's parse does (importers/volume/gdcm_parse_guard.h): a file that
/// kills the child is refused, never read in this process. Used for the header stage of every VTK
/// volume reader, the whole NIfTI read, the whole VTK mesh read (importers) and the VTK XML meshes
/// of a package (core/package/vtk_mesh_io.cpp: the package_folder fuzz target's SEGV in
/// vtkXMLReader::ReadXMLInformation).
///
/// Cost: one fork and the guarded read done twice (the second from the page cache).

#include <functional>

namespace viscera::core {

/// Seconds a guard's child may take before it is ended as hung: VTK's MINC reader loops for
/// ever on some damaged headers (the volume_minc fuzz target's timeout).
inline constexpr unsigned kGuardSeconds = 10;

/// Sets up a guard's freshly forked child: stderr to /dev/null (the parent reports) and the
/// default action for the deadly signals, so a fuzzer's or sanitizer's handler inherited from the
/// parent does not report a crash the guard exists to contain.
void prepare_guard_child();

/// Runs `attempt` in a forked child process prepared by prepare_guard_child(), with an alarm
/// after kGuardSeconds. True when the
/// child finished (returned or threw: a clean refusal the caller will meet again), false when a
/// signal ended it (a crash, an abort, or kGuardSeconds passed). Throws core::Error when no child
/// process can be started.
bool survives_in_child(const std::function<void()>& attempt);

}  // namespace viscera::core
