#pragma once
/// Writing an export of one or more files so that a failure leaves nothing: the writer fills a
/// temporary sibling folder of the target, and commit() moves its entries into place.

#include <filesystem>
#include <string>
#include <vector>

namespace viscera::exporters {

/// A hidden folder ".<name>.partial-<pid>-<n>" beside `target`, removed on destruction. Missing
/// folders on the way to `target` are created, and removed again when nothing is committed.
class StagedOutput {
 public:
  /// Creates the folder (and the target's missing parent folders); throws core::OutputError
  /// naming `target` when it cannot, e.g. when a parent is a file.
  explicit StagedOutput(const std::filesystem::path& target);
  ~StagedOutput();
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Where the writer puts the file named like the target (and its side files beside it).
  std::filesystem::path main_file() const { return folder_ / target_.filename(); }
  const std::filesystem::path& folder() const { return folder_; }

  /// Moves every entry of the folder beside the target, replacing older ones of the same name
  /// (each replacement is a rename, so a reader sees the old or the new file, never a mix).
  /// Returns the paths written, the target first. Throws core::OutputError naming the target.
  std::vector<std::filesystem::path> commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path folder_;
  std::filesystem::path created_;  ///< the outermost parent folder made here, or empty
  bool committed_ = false;
};

/// Writes `bytes` to `path` (a file inside a staging folder); throws core::OutputError naming
/// `shown`, the final target.
void write_bytes(const std::string& bytes, const std::filesystem::path& path,
                 const std::string& shown);

}  // namespace viscera::exporters
