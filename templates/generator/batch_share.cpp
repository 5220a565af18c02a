#include "templates/generator/batch_share.h"

#include <memory>

#include "core/error.h"
#include "core/package/scenario_package.h"

namespace viscera::templates {

NextPosition local_positions(std::size_t size) {
  auto taken = std::make_shared<std::size_t>(0);
  return [taken, size]() -> std::optional<std::size_t> {
    if (*taken >= size) return std::nullopt;
    return (*taken)++;
  };
}

ShareResult generate_patients(const VariantGenerator& generator, std::uint64_t count,
                              const std::vector<std::uint64_t>& indices, const NextPosition& next,
                              const std::filesystem::path& folder, const BatchJournal* journal,
                              core::Progress& progress) {
  std::filesystem::create_directories(folder);
  ShareResult result;
  progress.begin_stage("generating " + generator.scenario_template().name() + " patients",
                       static_cast<std::int64_t>(indices.size()));
  std::size_t reported = 0;
  while (const auto position = next()) {
    if (*position >= indices.size()) break;
    progress.step(static_cast<std::int64_t>(*position - std::min(*position, reported)));
    reported = std::max(reported, *position);
    const std::uint64_t k = indices[*position];
    if (k >= count) throw core::UsageError("patient index beyond the batch");
    const std::string package = patient_package_name(k, count);
    if (journal != nullptr) {
      if (auto kept = journal->kept_record(k, package)) {
        result.records.push_back(std::move(*kept));
        ++result.kept;
        continue;
      }
      journal->remove_stale_staging(package);
    }
    const GeneratedPatient patient = generator.generate(k, progress);
    core::write_package(patient.scenario, folder / package);
    nlohmann::json record = patient_record(patient, package);
    if (journal != nullptr) journal->record(k, record);
    result.records.push_back(std::move(record));
    ++result.generated;
  }
  progress.step(static_cast<std::int64_t>(indices.size() - std::min(indices.size(), reported)));
  return result;
}

}  // namespace viscera::templates
