#include "textures/parallel_rows.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace viscera::textures {

int default_thread_count() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void parallel_rows(int rows, const std::function<void(int begin, int end)>& work, int threads) {
  if (rows <= 0) return;
  if (threads <= 0) threads = default_thread_count();
  threads = std::min(threads, rows);
  if (threads == 1) {
    work(0, rows);
    return;
  }
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  std::vector<std::thread> pool;
  pool.reserve(errors.size());
  for (int t = 0; t < threads; ++t) {
    const int begin = static_cast<int>(static_cast<long long>(rows) * t / threads);
    const int end = static_cast<int>(static_cast<long long>(rows) * (t + 1) / threads);
    pool.emplace_back([&, t, begin, end] {
      try {
        work(begin, end);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  }
  for (auto& thread : pool)
    thread.join();
  for (const auto& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace viscera::textures
