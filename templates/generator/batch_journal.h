#pragma once
/// Resuming an interrupted batch (issue 20 §4): beside the packages, `viscera generate` keeps a
/// journal folder `.generate-journal/` with the batch's header and, per finished patient, its
/// index record and the SHA-256 of its package manifest, written only after the package is in
/// place. A run restarted with the same arguments keeps every patient whose journal entry
/// exists and whose package still reads back (read_package checks every file's checksum) with
/// that manifest, and generates only the others. The journal is removed when index.json is
/// written, so a finished batch holds only its packages and index.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace viscera::templates {

/// Name of the journal folder inside a batch folder.
inline constexpr const char* kJournalFolder = ".generate-journal";

/// The journal of one batch folder.
class BatchJournal {
 public:
  /// Opens (creating if missing) the journal of `folder` for the batch `header`
  /// (batch_header()). Throws core::UsageError naming the folder when it holds the journal of
  /// a batch with another header (template, seed, count or rules), core::OutputError when the
  /// journal cannot be written.
  BatchJournal(const std::filesystem::path& folder, const nlohmann::json& header);

  /// The record of patient `k` when a previous run finished it and its package `package`
  /// (relative to the folder) is intact; std::nullopt otherwise (never written, killed before
  /// the journal entry, package missing, edited or corrupt).
  std::optional<nlohmann::json> kept_record(std::uint64_t k, const std::string& package) const;

  /// Records patient `k` as finished: its index record and its package's manifest checksum.
  /// Call after the package is in place. Throws core::OutputError.
  void record(std::uint64_t k, const nlohmann::json& patient_record) const;

  /// Removes leftovers of a run killed while writing patient `package` (its staging folders
  /// ".<package>.tmp-*"): call only for a patient this process is about to generate.
  void remove_stale_staging(const std::string& package) const;

  /// Removes the journal of `folder` (after index.json is written).
  static void remove(const std::filesystem::path& folder);

 private:
  std::filesystem::path folder_;
  std::filesystem::path journal_;
};

}  // namespace viscera::templates
