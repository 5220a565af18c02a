#pragma once
/// Parallel loops over the lines of a 3D array (all i for one (j,k)), spread over the worker
/// threads by OpenMP's static schedule: the domain decomposition with a meeting point at the end
/// of each loop that seed 000 §9 describes for the fluid solver. Sums are reduced per line and
/// then added in line order, so every result is bit-identical for any number of threads. Loops
/// over a compact list (the active faces of the viscous step) go by fixed-size chunks alike.

#include <omp.h>

#include <algorithm>
#include <vector>

namespace viscera::sim::fluid {

/// Fewer lines than this run on the calling thread: the coarse multigrid levels (a few hundred
/// cells) cost less than waking the other threads.
inline constexpr int kParallelLines = 64;

/// Calls `line(j, k)` for every j < `ny`, k < `nz`, in parallel on `threads` threads (0: all).
template <typename Line>
void for_each_line(int ny, int nz, int threads, const Line& line) {
  const int lines = ny * nz;
#pragma omp parallel for schedule(static) \
    num_threads(threads > 0 ? threads : omp_get_max_threads()) if (lines >= kParallelLines)
  for (int l = 0; l < lines; ++l)
    line(l % ny, l / ny);
}

/// Σ over lines of `line(j, k)` (each line's sum), added in line order; `partials` is scratch.
template <typename Line>
double sum_over_lines(int ny, int nz, int threads, std::vector<double>& partials,
                      const Line& line) {
  const int lines = ny * nz;
  partials.resize(static_cast<std::size_t>(lines));
#pragma omp parallel for schedule(static) \
    num_threads(threads > 0 ? threads : omp_get_max_threads()) if (lines >= kParallelLines)
  for (int l = 0; l < lines; ++l)
    partials[static_cast<std::size_t>(l)] = line(l % ny, l / ny);
  double total = 0.0;
  for (const double p : partials)
    total += p;
  return total;
}

/// Calls `range(begin, end)` over `count` items cut into chunks of `chunk`, in parallel.
template <typename Range>
void for_each_chunk(int count, int chunk, int threads, const Range& range) {
  const int chunks = (count + chunk - 1) / chunk;
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int c = 0; c < chunks; ++c)
    range(c * chunk, std::min(count, (c + 1) * chunk));
}

/// Σ over chunks of `range(begin, end)` (each chunk's sum), added in chunk order: the chunks do
/// not depend on the thread count, so neither does the sum's rounding.
template <typename Range>
double sum_over_chunks(int count, int chunk, int threads, std::vector<double>& partials,
                       const Range& range) {
  const int chunks = (count + chunk - 1) / chunk;
  partials.resize(static_cast<std::size_t>(chunks));
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int c = 0; c < chunks; ++c)
    partials[static_cast<std::size_t>(c)] = range(c * chunk, std::min(count, (c + 1) * chunk));
  double total = 0.0;
  for (const double p : partials)
    total += p;
  return total;
}

}  // namespace viscera::sim::fluid
