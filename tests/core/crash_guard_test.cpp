// A guard's child (core/crash_guard.h) is bounded in memory as well as in time: an allocation
// past its limit ends it, and the guard reports the file as one the library cannot take (the
// volume_nifti fuzz target: 8.6 GB for a 384-byte header); an allocation within it passes. A
// child that waits on a lock another thread held at the fork is tried once more.
#include "core/crash_guard.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <thread>

namespace viscera::core {
namespace {

/// Where fill() leaves its buffer, so the compiler cannot elide the allocation.
char* volatile filled = nullptr;

/// Allocates `bytes` and writes every page, as a reader filling its buffer does.
void fill(std::size_t bytes) {
  const std::unique_ptr<char[]> buffer(new char[bytes]);
  std::memset(buffer.get(), 1, bytes);
  filled = buffer.get();
}

TEST(CrashGuard, a_child_that_allocates_past_its_limit_is_ended_and_within_it_passes) {
  if (!guard_limits_memory()) GTEST_SKIP() << "sanitizer build: guards do not limit memory";
  constexpr std::uint64_t kLimit = 256ULL << 20;
  EXPECT_TRUE(survives_in_child([] { fill(64ULL << 20); }, kLimit));
  EXPECT_FALSE(survives_in_child([] { fill(1ULL << 30); }, kLimit));
  // The same gigabyte is fine under a limit made for it.
  EXPECT_TRUE(survives_in_child([] { fill(1ULL << 30); }, guard_memory_for(1ULL << 30)));
}

TEST(CrashGuard, a_child_that_crashes_is_reported_and_one_that_refuses_is_not) {
  EXPECT_FALSE(survives_in_child([] { std::abort(); }));
  EXPECT_TRUE(survives_in_child([] { throw std::runtime_error("a clean refusal"); }));
}

TEST(CrashGuard, a_child_stuck_on_a_lock_held_at_the_fork_is_tried_again) {
  // What the sanitizer run met: a fork copies only the calling thread, so a lock another thread
  // held at that instant stays locked in the child for ever. The first child waits until the
  // guard's alarm; the second is forked after the lock was released and finishes.
  std::mutex lock;
  std::atomic<bool> held{false};
  std::thread holder([&] {
    const std::lock_guard<std::mutex> hold(lock);
    held = true;
    std::this_thread::sleep_for(std::chrono::seconds(1));
  });
  while (!held)
    std::this_thread::yield();
  const auto start = std::chrono::steady_clock::now();
  const bool survived = survives_in_child([&] { const std::lock_guard<std::mutex> take(lock); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  holder.join();
  EXPECT_TRUE(survived);
  EXPECT_GE(seconds, static_cast<double>(kGuardSeconds) - 0.5);  // the first child did wait
}

}  // namespace
}  // namespace viscera::core
