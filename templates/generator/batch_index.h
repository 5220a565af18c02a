#pragma once
/// The batch index (issue 6 §4–5): `index.json` beside the N packages of `viscera generate`,
/// with the batch's header (template, seed, count, rules, bounds), one record per patient
/// (parameters drawn, validation results, redraws), a redraw summary and the diversity summary.
/// Array jobs (`--shard I/N`) write partial indexes `index.shard-I-of-N.json` instead, which
/// merge_shards() combines into the same index.json a single run writes.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "templates/generator/variant_generator.h"

namespace viscera::templates {

inline constexpr const char* kIndexFormat = "viscera-generate-index";
inline constexpr int kIndexVersion = 1;

/// The header of a batch of `count` patients: format, version, template, template version,
/// seed, count, variability rules and the validation and simulation bounds.
nlohmann::json batch_header(const VariantGenerator& generator, std::uint64_t count);

/// The complete index: `header` + "patients" (records sorted by index) + "redraws" (total,
/// patients redrawn, by check) + "diversity" (parameter histograms, shape distances read from
/// the packages in `folder`). Throws core::ValidationError unless the records cover patients
/// 0 … count−1 exactly once.
nlohmann::json assemble_index(const nlohmann::json& header, nlohmann::json records,
                              const std::filesystem::path& folder);

/// File name of the partial index of shard `shard` of `shards`.
std::string shard_index_name(std::uint64_t shard, std::uint64_t shards);

/// Patients 0 … count−1 that shard `shard` of `shards` (0 ≤ shard < shards) generates:
/// k ≡ shard (mod shards), so every shard gets a spread of the batch.
std::vector<std::uint64_t> shard_indices(std::uint64_t count, std::uint64_t shard,
                                         std::uint64_t shards);

/// Writes `json` (2-space indented, final newline) to `path` through a temporary sibling and a
/// rename, so readers never see a partial file. Throws core::OutputError.
void write_json_atomically(const nlohmann::json& json, const std::filesystem::path& path);

/// Reads every `index.shard-*-of-N.json` in `folder`, checks that they share one header and
/// shard count and together cover the batch exactly once, writes `index.json` and removes the
/// partial indexes. Returns the index. Throws core::InputError (missing, unreadable or
/// inconsistent shards), core::ValidationError (patients missing or duplicated).
nlohmann::json merge_shards(const std::filesystem::path& folder);

}  // namespace viscera::templates
