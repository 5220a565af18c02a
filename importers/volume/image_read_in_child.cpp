#include "importers/volume/image_read_in_child.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <new>

#include "core/crash_guard.h"
#include "core/error.h"

namespace viscera::importers::detail {
namespace {

/// What the child sends before the voxels: plain numbers, checked by the parent.
struct ImageHeader {
  std::int32_t dimensions[3];
  double spacing[3];
  double origin[3];
  std::int32_t scalar_type;
  std::int32_t components;
  std::uint64_t bytes;
};

constexpr char kImage = 'I', kRefused = 'E';

bool write_all(int fd, const void* data, std::size_t size) {
  const char* at = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, at, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

/// Reads exactly `size` bytes; false at an early end (the child died while writing).
bool read_all(int fd, void* data, std::size_t size) {
  char* at = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::read(fd, at, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

void send_refusal(int fd, const std::string& reason) {
  const auto length = static_cast<std::uint32_t>(reason.size());
  (void)(write_all(fd, &kRefused, 1) && write_all(fd, &length, sizeof length) &&
         write_all(fd, reason.data(), reason.size()));
}

/// The child's side: read, then send the image or the reason it was refused.
void run_child(int fd, const std::function<vtkImageData*()>& read) {
  try {
    vtkImageData* image = read();
    vtkDataArray* scalars = image != nullptr ? image->GetPointData()->GetScalars() : nullptr;
    if (scalars == nullptr) {
      send_refusal(fd, "the reader produced no voxels");
      return;
    }
    ImageHeader header{};
    int dimensions[3];
    image->GetDimensions(dimensions);
    for (int a = 0; a < 3; ++a)
      header.dimensions[a] = dimensions[a];
    image->GetSpacing(header.spacing);
    image->GetOrigin(header.origin);
    header.scalar_type = scalars->GetDataType();
    header.components = scalars->GetNumberOfComponents();
    header.bytes = static_cast<std::uint64_t>(scalars->GetNumberOfValues()) *
                   static_cast<std::uint64_t>(scalars->GetDataTypeSize());
    if (write_all(fd, &kImage, 1) && write_all(fd, &header, sizeof header))
      write_all(fd, scalars->GetVoidPointer(0), header.bytes);
  } catch (const std::bad_alloc&) {
    send_refusal(fd, "reading it needs more memory than the image it declares");
  } catch (const core::Error& e) {
    send_refusal(fd, e.reason());
  } catch (const std::exception& e) {
    send_refusal(fd, e.what());
  }
}

/// Ends and reaps the child when the parent leaves early (a refusal or a failed allocation).
class ChildProcess {
 public:
  explicit ChildProcess(pid_t pid) : pid_(pid) {}
  ~ChildProcess() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Waits for the child; true when it exited normally.
  bool wait() {
    if (pid_ > 0) {
      while (::waitpid(pid_, &status_, 0) < 0) {
        if (errno != EINTR) break;
      }
      pid_ = -1;
    }
    return WIFEXITED(status_);
  }

  /// After wait(): the guard's alarm ended the child.
  bool timed_out() const { return core::ended_by_alarm(status_); }

 private:
  pid_t pid_;
  int status_ = 0;
};

/// One child's read ended by the guard's alarm: it may have waited on a lock
/// (core::kGuardAttempts).
struct TimedOut {};

/// The refusal of a file whose reader crashed, hung or ran out of memory in every child.
core::InputError crashed(const std::string& file, const std::string& reader) {
  return core::InputError(
      "the file is damaged: " + reader + " crashes, hangs or exhausts its memory on it",
      {file, "", ""});
}

/// Closes a pipe end on every path.
struct PipeEnd {
  int fd = -1;
  ~PipeEnd() {
    if (fd >= 0) ::close(fd);
  }
};

/// One child's read (read_image_in_child); throws TimedOut when the alarm ended the child.
vtkSmartPointer<vtkImageData> read_once(const std::function<vtkImageData*()>& read,
                                        const std::string& file, const std::string& reader,
                                        std::uint64_t memory_bytes) {
  int ends[2];
  if (::pipe(ends) != 0)
    throw core::Error(std::string("cannot start a process to read the file: ") +
                      std::strerror(errno));
  PipeEnd from_child{ends[0]}, to_parent{ends[1]};
  const pid_t pid = ::fork();
  if (pid < 0)
    throw core::Error(std::string("cannot start a process to read the file: ") +
                      std::strerror(errno));
  if (pid == 0) {
    ::close(from_child.fd);
    core::prepare_guard_child(memory_bytes);
    ::signal(SIGALRM, SIG_DFL);
    ::alarm(core::kGuardSeconds);
    run_child(to_parent.fd, read);
    ::_exit(0);  // nothing of the parent's state (atexit handlers, buffered streams) runs twice
  }
  ChildProcess child(pid);
  ::close(to_parent.fd);
  to_parent.fd = -1;

  const core::InputError crashed_error = crashed(file, reader);
  // After the child was waited for: the error, or TimedOut for another try.
  const auto ended = [&]() -> const core::InputError& {
    if (child.timed_out()) throw TimedOut{};
    return crashed_error;
  };
  char kind = 0;
  if (!read_all(from_child.fd, &kind, 1)) {
    child.wait();
    throw ended();
  }
  if (kind == kRefused) {
    std::uint32_t length = 0;
    std::string reason(0, '\0');
    if (read_all(from_child.fd, &length, sizeof length) && length <= (1u << 20)) {
      reason.resize(length);
      if (!read_all(from_child.fd, reason.data(), length)) reason.clear();
    }
    if (!child.wait()) throw ended();
    if (reason.empty()) throw crashed_error;
    throw core::InputError(reason, {file, "", ""});
  }
  ImageHeader header{};
  if (kind != kImage || !read_all(from_child.fd, &header, sizeof header)) {
    child.wait();
    throw ended();
  }
  // The numbers come from a process that ran a damaged file: checked before they size anything.
  std::uint64_t voxels = 1;
  for (const std::int32_t d : header.dimensions) {
    if (d < 1) throw core::InputError("the reader produced an empty image", {file, "", ""});
    voxels *= static_cast<std::uint64_t>(d);
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(header.dimensions[0], header.dimensions[1], header.dimensions[2]);
  image->SetSpacing(header.spacing);
  image->SetOrigin(header.origin);
  const auto scalars =
      vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(header.scalar_type));
  if (scalars == nullptr || header.components < 1 ||
      header.bytes != voxels * static_cast<std::uint64_t>(header.components) *
                          static_cast<std::uint64_t>(scalars->GetDataTypeSize()))
    throw crashed_error;
  scalars->SetNumberOfComponents(header.components);
  if (!scalars->SetNumberOfValues(static_cast<vtkIdType>(voxels) * header.components))
    throw core::InputError("the image is larger than memory can hold", {file, "", ""});
  if (!read_all(from_child.fd, scalars->GetVoidPointer(0), header.bytes)) {
    child.wait();
    throw ended();
  }
  if (!child.wait()) throw ended();
  image->GetPointData()->SetScalars(scalars);
  return image;
}

}  // namespace

vtkSmartPointer<vtkImageData> read_image_in_child(const std::function<vtkImageData*()>& read,
                                                  const std::string& file,
                                                  const std::string& reader,
                                                  std::uint64_t memory_bytes) {
  for (int tries = 1;; ++tries) {
    try {
      return read_once(read, file, reader, memory_bytes);
    } catch (const TimedOut&) {
      if (tries == core::kGuardAttempts) throw crashed(file, reader);
    }
  }
}

}  // namespace viscera::importers::detail
