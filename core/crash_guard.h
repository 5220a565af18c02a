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

#include <cstdint>
#include <functional>

namespace viscera::core {

/// Seconds a guard's child may take before it is ended as hung: VTK's MINC reader loops for
/// ever on some damaged headers (the volume_minc fuzz target's timeout).
inline constexpr unsigned kGuardSeconds = 10;

/// How many times a guard starts a child that its alarm ended before it refuses the file. A fork
/// copies only the calling thread, so a child can also wait for ever on a lock another thread of
/// the parent held at that instant: GCC 12's AddressSanitizer allocator is not fork-safe (LLVM
/// added its fork handlers in 2023, llvm-project pull request 75290; the sanitizer run's
/// TetMeshRoundTrip children waited on it while a TBB worker allocated), nor is every library's
/// own lock. Such a wait is rare and random where a reader's loop is not, so a second child
/// tells them apart; a file that hangs its reader is refused after 2 × kGuardSeconds.
inline constexpr int kGuardAttempts = 2;

/// True when the wait status `status` says the guard's alarm (kGuardSeconds) ended the child.
bool ended_by_alarm(int status);

/// Address space a guard's child may add to what it inherited when the caller knows no better
/// bound: a 384-byte NIfTI header made VTK's reader take 8.6 GB within the 10 s (volume_nifti fuzz
/// target). A reader that knows the size it will allocate passes its own (guard_memory_for).
inline constexpr std::uint64_t kGuardMemoryBytes = 4ULL << 30;

/// The bound for a child that reads `data_bytes` of declared data: twice that (a library's
/// buffer and its result) and 1 GiB for the library itself.
constexpr std::uint64_t guard_memory_for(std::uint64_t data_bytes) {
  return 2 * data_bytes + (1ULL << 30);
}

/// False in a build with AddressSanitizer or ThreadSanitizer: there guards do not limit memory.
bool guard_limits_memory();

/// Sets up a guard's freshly forked child: stderr to /dev/null (the parent reports); the default
/// action for the deadly signals, so a fuzzer's or sanitizer's handler inherited from the parent
/// does not report a crash the guard exists to contain; and its address space limited to what it
/// has plus `memory_bytes` (RLIMIT_AS), so an allocation past it fails and ends the child. Not
/// under AddressSanitizer or ThreadSanitizer, whose shadow memory the limit would refuse (the
/// fuzz build's libFuzzer bounds each allocation instead).
void prepare_guard_child(std::uint64_t memory_bytes = kGuardMemoryBytes);

/// In a child prepared by prepare_guard_child: bounds what it may still add to its address space
/// to `memory_bytes` for the stage that follows (the soft RLIMIT_AS, never above the prepared
/// bound), or lifts that back to the prepared bound with 0. For a reader whose first stage has a
/// tight bound and whose second needs room (gdcm_parse_guard.h). Nothing under the sanitizers.
void narrow_guard_child_memory(std::uint64_t memory_bytes);

/// Runs `attempt` in a forked child process prepared by prepare_guard_child(memory_bytes), with
/// an alarm after kGuardSeconds. True when the child finished (returned or threw: a clean refusal
/// the caller will meet again), false when a signal ended it (a crash, an abort, a failed
/// allocation past the limit, or kGuardSeconds passed in each of kGuardAttempts children).
/// Throws core::Error when no child process can be started.
bool survives_in_child(const std::function<void()>& attempt,
                       std::uint64_t memory_bytes = kGuardMemoryBytes);

}  // namespace viscera::core
