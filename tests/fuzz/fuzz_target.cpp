#include "tests/fuzz/fuzz_target.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <map>

#include "core/error.h"

namespace viscera::fuzz {
namespace fs = std::filesystem;

namespace {

std::map<std::string, TargetFunction>& registry() {
  static std::map<std::string, TargetFunction> targets;
  return targets;
}

fs::path scratch_folder() {
  const char* tmp = std::getenv("TMPDIR");
  const fs::path folder =
      fs::path(tmp && *tmp ? tmp : "/tmp") / ("viscera-fuzz-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  return folder;
}

void write_bytes(const fs::path& path, Bytes bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

/// An empty scratch folder for this input.
fs::path fresh_folder() {
  const fs::path folder = scratch_folder() / "folder";
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

/// `bytes` split at every "\n--\n".
std::vector<Bytes> chunks_of(Bytes bytes) {
  static constexpr std::uint8_t kMarker[] = {'\n', '-', '-', '\n'};
  std::vector<Bytes> chunks;
  std::size_t start = 0;
  while (start <= bytes.size()) {
    const auto rest = bytes.subspan(start);
    const auto end = std::search(rest.begin(), rest.end(), std::begin(kMarker), std::end(kMarker));
    const auto length = static_cast<std::size_t>(end - rest.begin());
    chunks.push_back(rest.first(length));
    start += length + sizeof(kMarker);
  }
  return chunks;
}

}  // namespace

bool register_target(const std::string& name, TargetFunction function) {
  registry()[name] = std::move(function);
  return true;
}

const TargetFunction* find_target(const std::string& name) {
  const auto found = registry().find(name);
  return found == registry().end() ? nullptr : &found->second;
}

std::vector<std::string> target_names() {
  std::vector<std::string> names;
  for (const auto& [name, function] : registry())
    names.push_back(name);
  return names;
}

void expect_typed_errors(const std::function<void()>& read) {
  try {
    read();
  } catch (const core::Error&) {
    // A refusal the user sees as one sentence: the behaviour wanted for bad bytes.
  }
}

fs::path input_file(Bytes bytes, const std::string& extension) {
  const fs::path path = scratch_folder() / ("input" + extension);
  write_bytes(path, bytes);
  return path;
}

fs::path input_folder(Bytes bytes, const std::string& extension) {
  const fs::path folder = fresh_folder();
  int n = 0;
  for (const Bytes chunk : chunks_of(bytes))
    write_bytes(folder / (std::to_string(n++) + extension), chunk);
  return folder;
}

fs::path input_named_folder(Bytes bytes) {
  const fs::path folder = fresh_folder();
  for (const Bytes chunk : chunks_of(bytes)) {
    const auto newline = std::find(chunk.begin(), chunk.end(), std::uint8_t{'\n'});
    if (newline == chunk.end()) continue;
    const fs::path name = fs::path(std::string(chunk.begin(), newline)).lexically_normal();
    if (name.empty() || name.is_absolute() || *name.begin() == ".." || !name.has_filename())
      continue;
    std::error_code error;
    fs::create_directories((folder / name).parent_path(), error);
    if (error) continue;
    write_bytes(folder / name,
                chunk.subspan(static_cast<std::size_t>(newline - chunk.begin()) + 1));
  }
  return folder;
}

}  // namespace viscera::fuzz
