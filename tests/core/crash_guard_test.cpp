// A guard's child (core/crash_guard.h) is bounded in memory as well as in time: an allocation
// past its limit ends it, and the guard reports the file as one the library cannot take (the
// volume_nifti fuzz target: 8.6 GB for a 384-byte header); an allocation within it passes.
#include "core/crash_guard.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <new>

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

}  // namespace
}  // namespace viscera::core
