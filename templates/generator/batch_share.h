#pragma once
/// One process's share of a batch (issue 20 §4): patients are handed out one at a time from a
/// list (a shard's or the whole batch's) by a position source — a counter of this process, or a
/// counter shared by every MPI rank so that a rank that finishes early takes the next patient
/// (dynamic load balancing). Every patient depends only on (template, seed, k), so who makes it
/// never changes its bytes. With a journal, patients a previous run finished are kept.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "core/progress.h"
#include "templates/generator/batch_journal.h"
#include "templates/generator/variant_generator.h"

namespace viscera::templates {

/// The next position (0, 1, 2, …) in the list being shared, each handed out once over all the
/// processes that share it; std::nullopt once the list is exhausted.
using NextPosition = std::function<std::optional<std::size_t>()>;

/// A position source for one process: 0, 1, …, size − 1.
NextPosition local_positions(std::size_t size);

/// What one share produced.
struct ShareResult {
  nlohmann::json records = nlohmann::json::array();  ///< in the order the patients were taken
  std::size_t generated = 0;  ///< patients generated and written by this process
  std::size_t kept = 0;       ///< patients a previous run had finished (journal), not redone
};

/// Takes positions from `next` until it is exhausted; for each, patient k = indices[position] of
/// the batch of `count`: kept from `journal` (when given) if a previous run finished it,
/// otherwise generated, written atomically into `folder` and then journalled. Progress counts
/// the positions handed out so far (over all processes). Throws as VariantGenerator::generate
/// and core::write_package, core::UsageError for an index beyond the batch.
ShareResult generate_patients(const VariantGenerator& generator, std::uint64_t count,
                              const std::vector<std::uint64_t>& indices, const NextPosition& next,
                              const std::filesystem::path& folder, const BatchJournal* journal,
                              core::Progress& progress = core::Progress::none());

}  // namespace viscera::templates
