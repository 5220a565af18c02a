#include "tests/fuzz/replay_limits.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

// The allocation limit replaces malloc; sanitizer builds keep their own allocator.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define VISCERA_REPLAY_LIMITS_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define VISCERA_REPLAY_LIMITS_MALLOC 0
#endif
#endif
#ifndef VISCERA_REPLAY_LIMITS_MALLOC
#define VISCERA_REPLAY_LIMITS_MALLOC 1
#endif

namespace {

// Plain data only: read inside malloc and a signal handler, where nothing may allocate.
char note_path[4096] = {};
char input_name[1024] = {};
volatile sig_atomic_t armed = 0;

void write_text(int fd, const char* text) {
  if (fd >= 0 && ::write(fd, text, std::strlen(text)) < 0) {
    // nothing more can be done from here
  }
}

/// Decimal digits of `value` in `out` (24 bytes).
void decimal(std::size_t value, char* out) {
  char digits[24];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + value % 10);
    value /= 10;
  } while (value > 0);
  for (int i = 0; i < n; ++i)
    out[i] = digits[n - 1 - i];
  out[n] = '\0';
}

void copy_text(char* to, std::size_t capacity, const std::string& from) {
  const std::size_t n = std::min(from.size(), capacity - 1);
  std::memcpy(to, from.data(), n);
  to[n] = '\0';
}

#if VISCERA_REPLAY_LIMITS_MALLOC  // the limit's own helpers: sanitizer builds do without
[[noreturn]] void allocation_over_limit(std::size_t size) {
  armed = 0;
  char number[24];
  decimal(size, number);
  const int note = ::open(note_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  for (const int out : {note, 2}) {
    write_text(out, "an allocation of ");
    write_text(out, number);
    write_text(out, " bytes, over the replay's limit of 2 GiB, while reading ");
    write_text(out, input_name);
    write_text(out, "\n");
  }
  if (note >= 0) ::close(note);
  std::abort();
}

/// True when a request of `size` bytes must fail; over the limit while armed, a finding.
bool must_fail(std::size_t size) {
  if (size > viscera::fuzz::kImpossibleBytes) return true;
  if (armed && size > viscera::fuzz::kAllocationLimitBytes) {
    // A guard's child bounded below the request (core/crash_guard.h): the product's own limit
    // refuses it, as the kernel would.
    rlimit bound{};
    if (::getrlimit(RLIMIT_AS, &bound) == 0 && bound.rlim_cur != RLIM_INFINITY &&
        size > bound.rlim_cur)
      return true;
    allocation_over_limit(size);
  }
  return false;
}
#endif

void on_alarm(int) {
  write_text(2, "viscera_fuzz_replay: ");
  write_text(2, input_name);
  char seconds[24];
  decimal(viscera::fuzz::kSecondsPerInput, seconds);
  write_text(2, " took longer than the replay's ");
  write_text(2, seconds);
  write_text(2, " s (a hang); stopping\n");
  // Own process group (start_replay_limits): the children a reader started go too.
  if (::getpgrp() == ::getpid()) ::kill(0, SIGKILL);
  ::raise(SIGKILL);
}

}  // namespace

#if VISCERA_REPLAY_LIMITS_MALLOC
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);

void* malloc(std::size_t size) noexcept {
  if (must_fail(size)) {
    errno = ENOMEM;
    return nullptr;
  }
  return __libc_malloc(size);
}

void* calloc(std::size_t count, std::size_t size) noexcept {
  if ((size != 0 && count > SIZE_MAX / size) || must_fail(count * size)) {
    errno = ENOMEM;
    return nullptr;
  }
  return __libc_calloc(count, size);
}

void* realloc(void* pointer, std::size_t size) noexcept {
  if (must_fail(size)) {
    errno = ENOMEM;
    return nullptr;
  }
  return __libc_realloc(pointer, size);
}
}
#endif

namespace viscera::fuzz {

void start_replay_limits(const std::filesystem::path& scratch) {
  ::setpgid(0, 0);  // may fail if already a group leader: then the alarm ends this process only
  copy_text(note_path, sizeof note_path, (scratch / "allocation-over-limit.txt").string());
  struct sigaction action {};
  action.sa_handler = on_alarm;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGALRM, &action, nullptr);
}

void begin_input(const std::string& input) {
  copy_text(input_name, sizeof input_name, input);
  ::unlink(note_path);
  armed = 1;
  ::alarm(kSecondsPerInput);
}

std::string end_input() {
  ::alarm(0);
  armed = 0;
  std::ifstream in(note_path);
  if (!in) return {};
  std::string note((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ::unlink(note_path);
  return note.empty() ? "a child process was stopped for an allocation over the limit" : note;
}

}  // namespace viscera::fuzz
