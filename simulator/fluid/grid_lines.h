#pragma once
/// Parallel loops over the lines of a 3D array (all i for one (j,k)), spread over the worker
/// threads by OpenMP's static schedule: the domain decomposition with a meeting point at the end
/// of each loop that seed 000 §9 describes for the fluid solver. Sums are reduced per line and
/// then added in line order, so every result is bit-identical for any number of threads.

#include <omp.h>

#include <vector>

namespace viscera::sim::fluid {

/// Calls `line(j, k)` for every j < `ny`, k < `nz`, in parallel on `threads` threads (0: all).
template <typename Line>
void for_each_line(int ny, int nz, int threads, const Line& line) {
  const int lines = ny * nz;
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int l = 0; l < lines; ++l)
    line(l % ny, l / ny);
}

/// Σ over lines of `line(j, k)` (each line's sum), added in line order; `partials` is scratch.
template <typename Line>
double sum_over_lines(int ny, int nz, int threads, std::vector<double>& partials,
                      const Line& line) {
  const int lines = ny * nz;
  partials.resize(static_cast<std::size_t>(lines));
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int l = 0; l < lines; ++l)
    partials[static_cast<std::size_t>(l)] = line(l % ny, l / ny);
  double total = 0.0;
  for (const double p : partials)
    total += p;
  return total;
}

}  // namespace viscera::sim::fluid
