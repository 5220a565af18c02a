#include "templates/generator/batch_index.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/json_numbers.h"
#include "templates/generator/batch_journal.h"
#include "templates/generator/diversity_summary.h"

namespace viscera::templates {
namespace fs = std::filesystem;

namespace {

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw core::InputError("cannot read the file", {path.string(), "", ""});
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw core::InputError(std::string("not valid JSON: ") + e.what(), {path.string(), "", ""});
  }
}

}  // namespace

nlohmann::json batch_header(const VariantGenerator& generator, std::uint64_t count) {
  const auto& o = generator.options();
  nlohmann::json rules = nlohmann::json::array();
  for (const auto& r : generator.rules()) {
    rules.push_back(
        {{"parameter", r.parameter}, {"distribution", r.distribution}, {"arguments", r.arguments}});
  }
  return {{"format", kIndexFormat},
          {"version", kIndexVersion},
          {"template", generator.scenario_template().name()},
          {"template_version", generator.scenario_template().version()},
          {"seed", generator.batch_seed()},
          {"count", count},
          {"variability", rules},
          {"validation_bounds",
           {{"min_dihedral_degrees", o.validation.min_dihedral_degrees},
            {"max_connection_gap", o.validation.max_connection_gap},
            {"wall_tolerance", o.validation.wall_tolerance},
            {"max_attempts", o.max_attempts},
            {"simulated_seconds", o.simulate ? o.simulation.duration : 0.0},
            {"max_displacement_fraction", o.simulation.max_displacement_fraction},
            {"max_speed", o.simulation.max_speed},
            {"perturbation", o.simulation.perturbation}}}};
}

nlohmann::json assemble_index(const nlohmann::json& header, nlohmann::json records,
                              const fs::path& folder) {
  const auto count =
      core::whole_number<std::uint64_t>(header.at("count"), folder.string(), "/count");
  for (std::size_t i = 0; i < records.size(); ++i)
    core::check_whole_numbers<std::uint64_t>(records[i].at("index"), folder.string(),
                                             "/patients/" + std::to_string(i) + "/index");
  std::vector<nlohmann::json> sorted(records.begin(), records.end());
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
    return a.at("index").template get<std::uint64_t>() <
           b.at("index").template get<std::uint64_t>();
  });
  for (std::uint64_t k = 0; k < count; ++k) {
    if (k >= sorted.size() || sorted[k].at("index").get<std::uint64_t>() != k) {
      throw core::ValidationError(
          "the batch lacks patient " + std::to_string(k) + " or holds a patient twice",
          {folder.string(), "", ""});
    }
  }
  if (sorted.size() != count)
    throw core::ValidationError("the batch holds more patients than its count",
                                {folder.string(), "", ""});
  nlohmann::json patients(sorted);
  std::uint64_t total = 0, redrawn = 0;
  std::map<std::string, std::uint64_t> by_check;
  for (const auto& p : patients) {
    const auto& r = p.at("redraws");
    total += r.size();
    if (!r.empty()) ++redrawn;
    for (const auto& d : r)
      ++by_check[d.at("check").get<std::string>()];
  }
  nlohmann::json index = header;
  index["patients"] = patients;
  index["redraws"] = {{"total", total}, {"patients_redrawn", redrawn}, {"by_check", by_check}};
  std::vector<core::VariabilityRule> rules;
  for (const auto& r : header.at("variability"))
    rules.push_back({r.at("parameter").get<std::string>(), r.at("distribution").get<std::string>(),
                     r.at("arguments")});
  const ScenarioTemplate& t = find_template(header.at("template").get<std::string>());
  std::set<std::string> distinct;
  for (const auto& p : patients)
    distinct.insert(p.at("parameters").dump());
  index["diversity"] = {{"distinct_parameter_sets", distinct.size()},
                        {"parameters", parameter_histograms(t, rules, patients)},
                        {"shape_distance", shape_distances(patients, folder)}};
  return index;
}

std::string shard_index_name(std::uint64_t shard, std::uint64_t shards) {
  return "index.shard-" + std::to_string(shard) + "-of-" + std::to_string(shards) + ".json";
}

std::vector<std::uint64_t> shard_indices(std::uint64_t count, std::uint64_t shard,
                                         std::uint64_t shards) {
  if (shards == 0 || shard >= shards)
    throw core::UsageError("shard " + std::to_string(shard) + "/" + std::to_string(shards) +
                           ": expected 0 <= I < N");
  std::vector<std::uint64_t> indices;
  for (std::uint64_t k = shard; k < count; k += shards)
    indices.push_back(k);
  return indices;
}

void write_json_atomically(const nlohmann::json& json, const fs::path& path) {
  // A name of this process's own: ranks and array jobs may write the same file at once.
  static std::atomic<unsigned> serial{0};
  const fs::path staged = path.string() + ".partial-" + std::to_string(::getpid()) + "-" +
                          std::to_string(serial.fetch_add(1));
  {
    std::ofstream out(staged, std::ios::binary | std::ios::trunc);
    out << json.dump(2) << "\n";
    if (!out) throw core::OutputError("cannot write the file", {staged.string(), "", ""});
  }
  std::error_code error;
  fs::rename(staged, path, error);
  if (error) {
    fs::remove(staged, error);
    throw core::OutputError("cannot move the file into place", {path.string(), "", ""});
  }
}

nlohmann::json merge_shards(const fs::path& folder) {
  if (!fs::is_directory(folder))
    throw core::InputError("no such folder", {folder.string(), "", ""});
  const std::regex name(R"(index\.shard-(\d+)-of-(\d+)\.json)");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (std::regex_match(entry.path().filename().string(), name)) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw core::InputError("no partial indexes (index.shard-I-of-N.json) to merge",
                           {folder.string(), "", ""});
  nlohmann::json header, records = nlohmann::json::array();
  std::set<std::uint64_t> shards_seen;
  std::uint64_t shards = 0;
  for (const auto& file : files) {
    nlohmann::json partial = read_json(file);
    if (!partial.is_object() || partial.value("format", "") != kIndexFormat ||
        !partial.contains("shard"))
      throw core::InputError("not a partial batch index", {file.string(), "", ""});
    const auto shard = core::whole_number<std::uint64_t>(partial.at("shard").at("index"),
                                                         file.string(), "/shard/index");
    const auto of = core::whole_number<std::uint64_t>(partial.at("shard").at("count"),
                                                      file.string(), "/shard/count");
    nlohmann::json partial_records = partial.at("patients");
    partial.erase("shard");
    partial.erase("patients");
    if (header.is_null()) header = partial, shards = of;
    if (partial != header || of != shards)
      throw core::InputError("partial index belongs to another batch", {file.string(), "", ""});
    shards_seen.insert(shard);
    for (auto& r : partial_records)
      records.push_back(std::move(r));
  }
  if (shards_seen.size() != shards) {
    throw core::InputError("found " + std::to_string(shards_seen.size()) + " of " +
                               std::to_string(shards) + " partial indexes",
                           {folder.string(), "", ""});
  }
  nlohmann::json index = assemble_index(header, records, folder);
  write_json_atomically(index, folder / "index.json");
  for (const auto& file : files)
    fs::remove(file);
  BatchJournal::remove(folder);
  return index;
}

}  // namespace viscera::templates
