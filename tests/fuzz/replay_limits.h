#pragma once
/// Limits the replay program (fuzz_replay.cpp) puts on every input, as libFuzzer's -malloc_limit_mb
/// and -timeout do in the fuzz build, so that the return of a fixed finding fails its FuzzReplay
/// test instead of passing slowly or taking the machine's memory:
///
/// - One allocation above kAllocationLimitBytes (malloc, calloc, realloc, and operator new, which
///   allocates through malloc) while an input is read is a finding: the replay writes a note and
///   aborts. A reader's crash guard runs the library in a forked child and would report that
///   child's end as a clean refusal, so end_input() also returns a note a child left. Requests
///   above kImpossibleBytes fail as they would anyway (no memory holds them; std::bad_alloc from
///   operator new), as ASan's allocator_may_return_null=1 does in the fuzz build.
/// - Each input has kSecondsPerInput seconds of wall-clock time. Then the replay kills its process
///   group (itself and any child a reader started) after naming the input on stderr.
///
/// The allocation limit is off in sanitizer builds (ASan has its own allocator); the clock is on.

#include <cstddef>
#include <filesystem>
#include <string>

#include "core/crash_guard.h"

namespace viscera::fuzz {

/// libFuzzer's default -malloc_limit_mb (its -rss_limit_mb, 2048).
inline constexpr std::size_t kAllocationLimitBytes = std::size_t{2048} << 20;
/// 1 TiB: more than any machine here holds.
inline constexpr std::size_t kImpossibleBytes = std::size_t{1} << 40;
/// Far above the slowest seed (well under a second), and above what a reader's crash guard may
/// take to refuse a file that hangs its library (core::kGuardAttempts children of
/// core::kGuardSeconds each): under ASan, where guards do not limit memory, the NIfTI finding's
/// child fills gigabytes until its alarm, twice, and the replay's former 20 s ended the input
/// the guard was about to refuse.
inline constexpr unsigned kSecondsPerInput = core::kGuardAttempts * core::kGuardSeconds + 20;

/// Makes the replay its own process group and names the note file (in `scratch`).
void start_replay_limits(const std::filesystem::path& scratch);

/// Arms the limits for `input` (named in the messages).
void begin_input(const std::string& input);

/// Disarms them; returns the note of an allocation over the limit made while the input was read,
/// here or in a forked child, or "" when there was none.
std::string end_input();

}  // namespace viscera::fuzz
