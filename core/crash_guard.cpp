#include "core/crash_guard.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "core/error.h"

namespace viscera::core {

void prepare_guard_child() {
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, 2);
  for (const int deadly : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL})
    ::signal(deadly, SIG_DFL);
}

bool survives_in_child(const std::function<void()>& attempt) {
  const pid_t child = ::fork();
  if (child < 0)
    throw Error(std::string("cannot start a process to check the file: ") + std::strerror(errno));
  if (child == 0) {
    prepare_guard_child();
    ::signal(SIGALRM, SIG_DFL);
    ::alarm(kGuardSeconds);  // a reader that loops is ended like one that crashes
    try {
      attempt();
    } catch (...) {  // a refusal: the parent's own attempt reports it
    }
    ::_exit(0);  // nothing of the parent's state (atexit handlers, buffered streams) runs twice
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return false;
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace viscera::core
