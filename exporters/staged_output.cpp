#include "exporters/staged_output.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>

#include "core/error.h"

namespace viscera::exporters {
namespace {

namespace fs = std::filesystem;

fs::path hidden_sibling(const fs::path& target, const char* kind) {
  static std::atomic<int> counter{0};
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string name = ".";
  name += target.filename().string();
  name += kind;
  name += std::to_string(getpid());
  name += "-";
  name += std::to_string(counter.fetch_add(1));
  return parent / name;
}

}  // namespace

StagedOutput::StagedOutput(const fs::path& target)
    : target_(target), folder_(hidden_sibling(target, ".partial-")) {
  std::error_code error;
  if (target_.filename().empty())
    throw core::UsageError("the output \"" + target.string() + "\" names no file");
  const fs::path parent = folder_.parent_path();
  if (!fs::is_directory(parent, error)) {
    // Create the missing folders, remembering the outermost so a failed export removes them.
    fs::path outermost = parent;
    while (outermost.has_parent_path() && outermost.parent_path() != outermost &&
           !fs::exists(outermost.parent_path(), error))
      outermost = outermost.parent_path();
    if (fs::exists(parent, error) || !fs::create_directories(parent, error) || error) {
      throw core::OutputError("cannot create the output folder " + parent.string() +
                                  (error ? ": " + error.message() : ": a file is in the way"),
                              {target.string(), "", ""});
    }
    created_ = outermost;
  }
  if (!fs::create_directory(folder_, error) || error) {
    throw core::OutputError(
        "cannot create a temporary folder beside the output: " + error.message(),
        {target.string(), "", ""});
  }
}

StagedOutput::~StagedOutput() {
  std::error_code ignored;
  fs::remove_all(folder_, ignored);
  if (!committed_ && !created_.empty()) fs::remove_all(created_, ignored);
}

std::vector<fs::path> StagedOutput::commit() {
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(folder_))
    entries.push_back(entry.path());
  std::sort(entries.begin(), entries.end());
  const auto main = std::find(entries.begin(), entries.end(), main_file());
  if (main == entries.end())
    throw core::OutputError("the writer produced no file", {target_.string(), "", ""});
  // Side files first and the main file last, so that a reader who sees the main file finds
  // everything it names.
  std::rotate(main, main + 1, entries.end());
  const fs::path parent = target_.parent_path();  // empty: the current folder
  // Refuse to replace a folder by a file or a file by a folder: that is not an older export.
  for (const auto& entry : entries) {
    const fs::path destination = parent / entry.filename();
    if (fs::exists(destination) && fs::is_directory(destination) != fs::is_directory(entry)) {
      throw core::OutputError("cannot replace \"" + destination.string() + "\": it is a " +
                                  (fs::is_directory(destination) ? "folder" : "file") +
                                  " of another kind",
                              {target_.string(), "", ""});
    }
  }
  // Older versions step aside, the new entries move in; on any failure the new ones are removed
  // and the old ones put back, so the target is either wholly old or wholly new.
  std::vector<std::pair<fs::path, fs::path>> set_aside;  // destination → backup
  std::vector<fs::path> written;
  try {
    for (const auto& entry : entries) {
      const fs::path destination = parent / entry.filename();
      if (fs::exists(destination)) {
        const fs::path backup = hidden_sibling(destination, ".old-");
        fs::rename(destination, backup);
        set_aside.emplace_back(destination, backup);
      }
      fs::rename(entry, destination);
      written.push_back(destination);
    }
  } catch (const fs::filesystem_error& e) {
    std::error_code ignored;
    for (const auto& path : written)
      fs::remove_all(path, ignored);
    for (const auto& [destination, backup] : set_aside)
      fs::rename(backup, destination, ignored);
    throw core::OutputError(std::string("cannot move the export into place: ") + e.what(),
                            {target_.string(), "", ""});
  }
  std::error_code ignored;
  for (const auto& [destination, backup] : set_aside)
    fs::remove_all(backup, ignored);
  std::rotate(written.rbegin(), written.rbegin() + 1, written.rend());  // the main file first
  committed_ = true;
  return written;
}

void write_bytes(const std::string& bytes, const fs::path& path, const std::string& shown) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw core::OutputError("cannot write " + path.filename().string(), {shown, "", ""});
}

}  // namespace viscera::exporters
