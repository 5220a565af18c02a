#include "studio/cli/generate_commands.h"

#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "studio/cli/command_output.h"
#include "studio/cli/mpi_ranks.h"
#include "studio/cli/terminal_progress.h"
#include "templates/generator/batch_index.h"
#include "templates/generator/batch_journal.h"
#include "templates/generator/batch_share.h"
#include "templates/variability/parameter_distribution.h"

namespace viscera::cli {
namespace fs = std::filesystem;
namespace {

struct GenerateOptions {
  std::string template_name;
  std::uint64_t count = 0;
  std::uint64_t seed = 1;
  std::string output;
  std::string shard;
  std::string merge;
  std::vector<std::string> settings;
  int max_attempts = 25;
  bool json = false;
};

/// "I/N" → (I, N) with 0 ≤ I < N.
std::pair<std::uint64_t, std::uint64_t> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  try {
    if (slash != std::string::npos) {
      std::size_t used_i = 0, used_n = 0;
      const std::string i_text = text.substr(0, slash), n_text = text.substr(slash + 1);
      const auto i = std::stoull(i_text, &used_i);
      const auto n = std::stoull(n_text, &used_n);
      if (used_i == i_text.size() && used_n == n_text.size() && n > 0 && i < n) return {i, n};
    }
  } catch (const std::exception&) {
  }
  throw core::UsageError("--shard expects I/N with 0 <= I < N, got \"" + text + "\"");
}

/// The template's own rules, with every --set name=value turned into a fixed rule.
std::vector<core::VariabilityRule> batch_rules(const templates::ScenarioTemplate& t,
                                               const std::vector<std::string>& settings) {
  std::map<std::string, std::string> overrides;
  for (const auto& s : settings) {
    const auto equals = s.find('=');
    if (equals == std::string::npos || equals == 0)
      throw core::UsageError("--set expects name=value, got \"" + s + "\"");
    overrides[s.substr(0, equals)] = s.substr(equals + 1);
  }
  const templates::ParameterValues fixed = templates::resolve_parameters(t, overrides);
  std::vector<core::VariabilityRule> rules;
  for (const auto& rule : t.default_variability()) {
    if (!overrides.contains(rule.parameter)) rules.push_back(rule);
  }
  for (const auto& [name, text] : overrides)
    rules.push_back(templates::fixed_rule(name, fixed.at(name)));
  return rules;
}

/// Prints what the run wrote; `generated` and `kept` count this run's patients (kept: finished
/// by an interrupted run of the same batch).
void report(const nlohmann::json& index, const fs::path& folder, bool json, bool partial,
            std::size_t generated, std::size_t kept) {
  const fs::path where = fs::absolute(folder).lexically_normal();
  if (json) {
    nlohmann::json out = {{"folder", where.string()},
                          {"template", index.at("template")},
                          {"seed", index.at("seed")},
                          {"count", index.at("count")},
                          {"patients", index.at("patients").size()},
                          {"partial", partial},
                          {"generated", generated},
                          {"kept", kept}};
    if (index.contains("redraws")) out["redraws"] = index.at("redraws");
    if (index.contains("diversity")) {
      out["distinct_parameter_sets"] = index.at("diversity").at("distinct_parameter_sets");
      out["shape_distance"] = index.at("diversity").at("shape_distance");
    }
    print_json(out);
    return;
  }
  std::ostringstream out;
  std::size_t redraws = 0;
  for (const auto& p : index.at("patients"))
    redraws += p.at("redraws").size();
  out << "wrote " << index.at("patients").size() << " validated "
      << index.at("template").get<std::string>() << " patients (" << redraws
      << " invalid draws redrawn) and " << (partial ? "a partial index" : "index.json") << " to "
      << where.string();
  if (kept > 0)
    out << " (" << kept << " kept from an interrupted run, " << generated << " generated)";
  out << "\n";
  print_text(out.str());
}

/// Generates this rank's share and, on rank 0, writes the index. Returns the exit code, the
/// same on every rank.
int generate(const GenerateOptions& o) {
  MpiRanks ranks;
  // Collective, so before anything that may throw on one rank only.
  MpiSharedCounter counter(ranks);
  const fs::path folder = o.output;
  nlohmann::json payload;
  nlohmann::json header;
  std::optional<std::pair<std::uint64_t, std::uint64_t>> shard;
  try {
    if (o.count == 0) throw core::UsageError("--count must be at least 1");
    if (!o.shard.empty()) shard = parse_shard(o.shard);
    const templates::ScenarioTemplate& t = templates::find_template(o.template_name);
    templates::GenerationOptions options;
    options.max_attempts = o.max_attempts;
    const templates::VariantGenerator generator(t, batch_rules(t, o.settings), o.seed, options);
    header = templates::batch_header(generator, o.count);
    const auto indices = shard ? templates::shard_indices(o.count, shard->first, shard->second)
                               : templates::shard_indices(o.count, 0, 1);
    // Patients a previous run of the same batch finished are kept (resume after a kill).
    const templates::BatchJournal journal(folder, header);
    // Ranks take the next patient of the share from a counter on rank 0 when they are free:
    // patients differ in cost (redraws), so a fixed split leaves one rank waiting.
    const templates::NextPosition next = [&counter]() -> std::optional<std::size_t> {
      return static_cast<std::size_t>(counter.fetch_and_increment());
    };
    TerminalProgress bar;
    const templates::ShareResult share =
        templates::generate_patients(generator, o.count, indices, next, folder, &journal,
                                     ranks.rank() == 0 ? bar.progress() : core::Progress::none());
    payload = {{"ok", true},
               {"records", share.records},
               {"generated", share.generated},
               {"kept", share.kept}};
  } catch (const std::exception& e) {
    payload = {
        {"ok", false}, {"error", e.what()}, {"exit", static_cast<int>(core::exit_code_for(e))}};
  }
  const std::vector<std::string> parts = ranks.gather(payload.dump());
  int code = 0;
  if (ranks.rank() == 0) {
    try {
      nlohmann::json records = nlohmann::json::array();
      std::size_t generated = 0, kept = 0;
      for (std::size_t r = 0; r < parts.size(); ++r) {
        const nlohmann::json part = nlohmann::json::parse(parts[r]);
        if (!part.at("ok").get<bool>()) {
          std::cerr << "viscera: " << (ranks.size() > 1 ? "rank " + std::to_string(r) + ": " : "")
                    << part.at("error").get<std::string>() << "\n";
          if (code == 0) code = part.at("exit").get<int>();
          continue;
        }
        for (const auto& record : part.at("records"))
          records.push_back(record);
        generated += part.at("generated").get<std::size_t>();
        kept += part.at("kept").get<std::size_t>();
      }
      if (code == 0) {
        if (shard) {
          nlohmann::json partial = header;
          std::vector<nlohmann::json> sorted(records.begin(), records.end());
          std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
            return a.at("index").template get<std::uint64_t>() <
                   b.at("index").template get<std::uint64_t>();
          });
          partial["shard"] = {{"index", shard->first}, {"count", shard->second}};
          partial["patients"] = sorted;
          templates::write_json_atomically(
              partial, folder / templates::shard_index_name(shard->first, shard->second));
          report(partial, folder, o.json, true, generated, kept);
        } else {
          const nlohmann::json index = templates::assemble_index(header, records, folder);
          templates::write_json_atomically(index, folder / "index.json");
          templates::BatchJournal::remove(folder);
          report(index, folder, o.json, false, generated, kept);
        }
      }
    } catch (const std::exception& e) {
      std::cerr << "viscera: " << e.what() << "\n";
      code = static_cast<int>(core::exit_code_for(e));
    }
  }
  return ranks.broadcast(code);
}

int merge(const GenerateOptions& o) {
  const nlohmann::json index = templates::merge_shards(o.merge);
  report(index, o.merge, o.json, false, 0, 0);
  return 0;
}

}  // namespace

void add_generate_commands(CLI::App& app, int& exit_code) {
  auto* command = app.add_subcommand(
      "generate",
      "Generate validated virtual patients from a template (under mpirun: one share per rank)");
  auto o = std::make_shared<GenerateOptions>();
  command->add_option("--template,-t", o->template_name, "Template name");
  command->add_option("--count,-n", o->count, "Number of patients");
  command->add_option("--seed", o->seed, "Batch seed")->capture_default_str();
  command->add_option("-o,--output", o->output, "Output folder");
  command->add_option("--set", o->settings,
                      "Fix a parameter for the whole batch: name=value (repeatable)");
  command->add_option("--shard", o->shard,
                      "Generate only shard I of N (0 <= I < N) and write a partial index");
  command->add_option("--merge", o->merge,
                      "Combine the partial indexes in this folder into index.json");
  command->add_option("--max-attempts", o->max_attempts, "Draws per patient before giving up")
      ->capture_default_str();
  command->add_flag("--json", o->json, "Print JSON");
  command->callback([o, &exit_code] {
    if (!o->merge.empty()) {
      if (!o->template_name.empty() || o->count != 0 || !o->output.empty() || !o->shard.empty())
        throw core::UsageError("--merge DIR takes no other batch options");
      exit_code = merge(*o);
      return;
    }
    if (o->template_name.empty() || o->count == 0 || o->output.empty())
      throw core::UsageError("generate needs --template, --count and -o (or --merge DIR)");
    exit_code = generate(*o);
  });
}

}  // namespace viscera::cli
