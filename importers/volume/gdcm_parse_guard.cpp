#include "importers/volume/gdcm_parse_guard.h"

#include <fcntl.h>
#include <gdcmImageReader.h>
#include <gdcmReader.h>
#include <gdcmTrace.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <new>
#include <system_error>

#include "core/crash_guard.h"
#include "core/error.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

/// The child's side: announces each file's stage on `out` before it runs — 2i before the parse
/// of file i, 2i + 1 before its image read — then -1 when all are done, and leaves with _exit so
/// nothing of the parent's state (atexit handlers, buffered streams) runs twice.
[[noreturn]] void parse_in_child(const std::vector<fs::path>& files, std::size_t first, int out) {
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetError(false);
  gdcm::Trace::SetDebug(false);
  // Assertion messages would reach the user's terminal: the parent reports instead. GDCM holds
  // one file at a time. Its parse is bounded by the file's size: when its first reading of a
  // damaged file fails, GDCM parses it again in recovery modes (16-bit lengths, then implicit
  // VR) whose misread lengths the element walk cannot foresee, and zero-fills what they declare
  // (stop 20's volume_dicom_file finding: 4.2 GB for 6 s, now refused at once). The bound keeps
  // 2 GiB of room: GDCM maps 1.3 GB while it parses pydicom's valid 4 KB SC_rgb_jpeg.dcm. The
  // image read gets the default's room.
  core::prepare_guard_child(core::kGuardMemoryBytes);
  // GDCM catches a failed allocation and parses on (to an assertion the parent would meet
  // unbounded): here a failed allocation ends the child, which refuses the file.
  std::set_new_handler([] { ::_exit(3); });
  ::signal(SIGALRM, SIG_DFL);
  const auto announce = [out](std::int64_t stage) {
    if (::write(out, &stage, sizeof stage) != sizeof stage) ::_exit(2);
  };
  for (std::size_t i = first; i < files.size(); ++i) {
    const auto index = static_cast<std::int64_t>(i);
    const std::string name = files[i].string();
    announce(2 * index);
    ::alarm(core::kGuardSeconds);  // each read: one that hangs is refused like a crash
    std::error_code error;
    const std::uintmax_t size = fs::file_size(files[i], error);
    core::narrow_guard_child_memory(core::guard_memory_for(error ? 0 : size) + (1ULL << 30));
    gdcm::Reader parser;
    parser.SetFileName(name.c_str());
    const bool parsed = parser.Read();
    announce(2 * index + 1);
    ::alarm(core::kGuardSeconds);
    core::narrow_guard_child_memory(0);
    // The image reader, as the parent reads an image: it parses the data elements again and then
    // interprets the image's attributes (spacing, origin, pixel format), where GDCM asserts too.
    if (parsed) {
      gdcm::ImageReader reader;
      reader.SetFileName(name.c_str());
      reader.Read();
    }
  }
  const std::int64_t done = -1;
  const bool written = ::write(out, &done, sizeof done) == sizeof done;
  ::_exit(written ? 0 : 2);
}

/// Reads the child's announcements until end of file; returns the last index announced, or -1
/// when the child finished (announced -1) or announced nothing.
std::int64_t last_announced(int in) {
  std::int64_t last = -1, value = 0;
  for (;;) {
    const ssize_t got = ::read(in, &value, sizeof value);
    if (got == sizeof value) {
      last = value;
      continue;
    }
    if (got < 0 && errno == EINTR) continue;
    return last;
  }
}

}  // namespace

std::vector<GdcmGuardResult> gdcm_reads_without_abort(const std::vector<fs::path>& files) {
  std::vector<GdcmGuardResult> results(files.size());
  std::size_t first = 0;
  // The stage whose child the alarm ended once: its file is read once more
  // (core::kGuardAttempts).
  std::int64_t timed_out_once = -1;
  while (first < files.size()) {
    int channel[2];
    if (::pipe(channel) != 0) throw core::Error("cannot open a pipe to check DICOM files");
    const pid_t child = ::fork();
    if (child < 0) {
      ::close(channel[0]);
      ::close(channel[1]);
      throw core::Error("cannot start a process to check DICOM files");
    }
    if (child == 0) {
      ::close(channel[0]);
      parse_in_child(files, first, channel[1]);
    }
    ::close(channel[1]);
    const std::int64_t last = last_announced(channel[0]);
    ::close(channel[0]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    const bool finished = WIFEXITED(status) && WEXITSTATUS(status) == 0 && last == -1;
    if (finished) break;
    if (last < 0) throw core::Error("the process checking DICOM files failed to report");
    const auto file = static_cast<std::size_t>(last / 2);
    if (core::ended_by_alarm(status) && last != timed_out_once) {
      static_assert(core::kGuardAttempts == 2, "one more child for a file that timed out");
      timed_out_once = last;
      first = file;
      continue;
    }
    results[file].image_reads = false;
    if (last % 2 == 0) results[file].parses = false;
    first = file + 1;
  }
  return results;
}

}  // namespace viscera::importers::detail
