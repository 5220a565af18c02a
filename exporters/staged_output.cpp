#include "exporters/staged_output.h"

#include <algorithm>
#include <fstream>

#include "core/atomic_replace.h"
#include "core/error.h"

namespace viscera::exporters {
namespace fs = std::filesystem;

StagedOutput::StagedOutput(const fs::path& target)
    : target_(target), folder_(core::staging_sibling(target, ".partial-")) {
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
  // Each entry replaces its older version in one atomic step (a file by rename, a folder by an
  // exchange), so a crash at any moment leaves every name wholly old or wholly new. The older
  // versions are kept under hidden names until all entries are in, so that a failure half-way
  // puts every one of them back.
  std::vector<std::pair<fs::path, fs::path>> set_aside;  // destination → older version
  std::vector<fs::path> written;
  try {
    for (const auto& entry : entries) {
      const fs::path destination = parent / entry.filename();
      if (fs::is_directory(destination)) {
        core::exchange_atomically(entry, destination);  // `entry` now holds the older folder
        set_aside.emplace_back(destination, entry);
      } else {
        if (fs::exists(destination)) {
          const fs::path older = core::staging_sibling(destination, ".old-");
          fs::create_hard_link(destination, older);
          set_aside.emplace_back(destination, older);
        }
        core::replace_atomically(entry, destination);
      }
      written.push_back(destination);
    }
  } catch (const std::exception& e) {
    std::error_code ignored;
    for (const auto& [destination, older] : set_aside)
      fs::rename(older, destination, ignored);
    for (const auto& path : written) {
      if (std::none_of(set_aside.begin(), set_aside.end(),
                       [&](const auto& pair) { return pair.first == path; }))
        fs::remove_all(path, ignored);
    }
    throw core::OutputError(std::string("cannot move the export into place: ") + e.what(),
                            {target_.string(), "", ""});
  }
  std::error_code ignored;
  for (const auto& [destination, older] : set_aside)
    fs::remove_all(older, ignored);
  core::remove_abandoned_staging(target_);
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
