#pragma once
/// Row-parallel loops for texture work. Rows are split into fixed contiguous bands and every
/// row is computed independently, so results never depend on the number of threads.

#include <functional>

namespace viscera::textures {

/// Calls work(begin, end) on disjoint bands covering [0, rows) from up to `threads` threads
/// (0 = one per hardware thread) and waits for all. The first exception thrown by any band is
/// rethrown after all bands finish.
void parallel_rows(int rows, const std::function<void(int begin, int end)>& work, int threads = 0);

/// Number of threads parallel_rows uses for `threads` = 0.
int default_thread_count();

}  // namespace viscera::textures
