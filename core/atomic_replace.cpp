#include "core/atomic_replace.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include "core/error.h"

namespace viscera::core {
namespace {

namespace fs = std::filesystem;

fs::path parent_of(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

/// The process id in a staging name ".<name><kind><pid>-<n>" after `prefix` ".<name>", or 0.
pid_t staging_owner(const std::string& entry, const std::string& prefix) {
  if (entry.rfind(prefix, 0) != 0) return 0;
  for (const char* kind : {".tmp-", ".partial-", ".old-"}) {
    const std::string head = prefix + kind;
    if (entry.rfind(head, 0) != 0) continue;
    const std::string rest = entry.substr(head.size());
    const auto dash = rest.find('-');
    if (dash == std::string::npos || dash == 0) return 0;
    pid_t pid = 0;
    for (std::size_t i = 0; i < dash; ++i) {
      if (rest[i] < '0' || rest[i] > '9') return 0;
      pid = pid * 10 + (rest[i] - '0');
    }
    return pid;
  }
  return 0;
}

}  // namespace

fs::path staging_sibling(const fs::path& target, const char* kind) {
  static std::atomic<int> counter{0};
  return parent_of(target) / ("." + target.filename().string() + kind + std::to_string(getpid()) +
                              "-" + std::to_string(counter.fetch_add(1)));
}

void exchange_atomically(const fs::path& a, const fs::path& b) {
  if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) != 0) {
    throw OutputError(std::string("cannot put the new output in place: ") + std::strerror(errno),
                      {b.string(), "", ""});
  }
}

void replace_atomically(const fs::path& staged, const fs::path& target) {
  std::error_code error;
  const bool folder = fs::is_directory(staged, error) || fs::is_directory(target, error);
  if (folder && fs::exists(target, error)) {
    exchange_atomically(staged, target);
    fs::remove_all(staged, error);  // now the old output
    return;
  }
  if (::rename(staged.c_str(), target.c_str()) != 0) {
    throw OutputError(std::string("cannot put the new output in place: ") + std::strerror(errno),
                      {target.string(), "", ""});
  }
}

int remove_abandoned_staging(const fs::path& target) {
  std::error_code error;
  // A zipped package is assembled in a folder staged as "<name>-folder".
  const std::string prefix = "." + target.filename().string();
  int removed = 0;
  for (fs::directory_iterator it(parent_of(target), error), end; !error && it != end;
       it.increment(error)) {
    const std::string entry = it->path().filename().string();
    pid_t owner = staging_owner(entry, prefix);
    if (owner <= 0) owner = staging_owner(entry, prefix + "-folder");
    if (owner <= 0 || owner == getpid()) continue;
    if (::kill(owner, 0) == 0 || errno != ESRCH) continue;  // still running (or not ours)
    std::error_code ignored;
    if (fs::remove_all(it->path(), ignored) > 0) ++removed;
  }
  return removed;
}

}  // namespace viscera::core
