#include "core/crash_guard.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>
#include <string>

#include "core/error.h"

namespace viscera::core {

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

/// Bytes of address space this process maps now (/proc/self/statm, first field), or 0.
std::uint64_t mapped_bytes() {
  const int fd = ::open("/proc/self/statm", O_RDONLY);
  if (fd < 0) return 0;
  char text[64] = {};
  const ssize_t n = ::read(fd, text, sizeof text - 1);
  ::close(fd);
  if (n <= 0) return 0;
  std::uint64_t pages = 0;
  for (const char* c = text; *c >= '0' && *c <= '9'; ++c)
    pages = pages * 10 + static_cast<std::uint64_t>(*c - '0');
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

bool guard_limits_memory() {
  return !kSanitized;
}

void prepare_guard_child(std::uint64_t memory_bytes) {
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, 2);
  for (const int deadly : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL})
    ::signal(deadly, SIG_DFL);
  if (!kSanitized) {
    const std::uint64_t mapped = mapped_bytes();
    if (mapped > 0) {
      const rlimit limit{mapped + memory_bytes, mapped + memory_bytes};
      ::setrlimit(RLIMIT_AS, &limit);
    }
  }
}

void narrow_guard_child_memory(std::uint64_t memory_bytes) {
  if (kSanitized) return;
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0) return;
  const std::uint64_t mapped = mapped_bytes();
  limit.rlim_cur = memory_bytes == 0 || mapped == 0
                       ? limit.rlim_max
                       : std::min<rlim_t>(limit.rlim_max, mapped + memory_bytes);
  ::setrlimit(RLIMIT_AS, &limit);
}

bool ended_by_alarm(int status) {
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM;
}

bool survives_in_child(const std::function<void()>& attempt, std::uint64_t memory_bytes) {
  for (int tries = 1;; ++tries) {
    const pid_t child = ::fork();
    if (child < 0) {
      throw Error(std::string("cannot start a process to check the file: ") + std::strerror(errno));
    }
    if (child == 0) {
      prepare_guard_child(memory_bytes);
      ::signal(SIGALRM, SIG_DFL);
      ::alarm(kGuardSeconds);  // a reader that loops is ended like one that crashes
      try {
        attempt();
      } catch (const std::bad_alloc&) {  // past the limit: the parent must not try it unbounded
        ::_exit(3);
      } catch (...) {  // a refusal: the parent's own attempt reports it
      }
      ::_exit(0);  // nothing of the parent's state (atexit handlers, buffered streams) runs twice
    }
    int status = 0;
    while (::waitpid(child, &status, 0) < 0) {
      if (errno != EINTR) return false;
    }
    if (ended_by_alarm(status) && tries < kGuardAttempts) continue;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
  }
}

}  // namespace viscera::core
