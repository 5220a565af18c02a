#include "core/scenario/procedure.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/error.h"
#include "core/json_text.h"
#include "core/scenario/procedure_data.h"
#include "core/scenario/scenario_json.h"

namespace viscera::core {
namespace {

/// Checks what the JSON types alone cannot: unique ids, no empty step or substep, limits ≥ 0.
void check_procedure(const ProcedureDefinition& p, const std::string& file) {
  const auto fail = [&file](const std::string& pointer, const std::string& message) {
    throw ValidationError(message, {file, pointer, ""});
  };
  if (p.name.empty()) fail("/name", "a procedure needs a name");
  if (p.steps.empty()) fail("/steps", "a procedure needs at least one step");
  if (!(p.duration_limit > 0.0)) fail("/duration_limit", "duration limit must be positive (s)");
  if (!(p.force_warning >= 0.0)) fail("/force_warning", "force warning level must be ≥ 0 (N)");
  if (!(p.perforation_depth >= 0.0))
    fail("/perforation_depth", "perforation depth must be ≥ 0 (m)");
  std::set<std::string> ids;
  for (std::size_t s = 0; s < p.steps.size(); ++s) {
    const auto& step = p.steps[s];
    const std::string sp = "/steps/" + std::to_string(s);
    if (!ids.insert(step.id).second) fail(sp + "/id", "duplicate id \"" + step.id + "\"");
    if (step.substeps.empty()) fail(sp + "/substeps", "step \"" + step.id + "\" has no substeps");
    for (std::size_t u = 0; u < step.substeps.size(); ++u) {
      const auto& substep = step.substeps[u];
      const std::string up = sp + "/substeps/" + std::to_string(u);
      if (!ids.insert(substep.id).second) fail(up + "/id", "duplicate id \"" + substep.id + "\"");
      if (substep.tasks.empty()) fail(up + "/tasks", "substep \"" + substep.id + "\" has no tasks");
      for (std::size_t t = 0; t < substep.tasks.size(); ++t) {
        const auto& task = substep.tasks[t];
        if (!ids.insert(task.id).second)
          fail(up + "/tasks/" + std::to_string(t) + "/id", "duplicate id \"" + task.id + "\"");
        if (!task.parameters.is_object())
          fail(up + "/tasks/" + std::to_string(t) + "/parameters", "parameters must be an object");
      }
    }
  }
}

const std::map<std::string, ProcedureDefinition>& builtin_procedures() {
  static const std::map<std::string, ProcedureDefinition> procedures = [] {
    std::map<std::string, ProcedureDefinition> out;
    for (const char* text : builtin_procedure_documents()) {
      ProcedureDefinition p = procedure_from_json(nlohmann::json::parse(text), "data/procedures");
      const std::string name = p.name;
      out.emplace(name, std::move(p));
    }
    return out;
  }();
  return procedures;
}

}  // namespace

ProcedureDefinition procedure_from_json(const nlohmann::json& j, const std::string& file) {
  if (!has_format(j, "viscera-procedure")) {
    throw ValidationError("not a Viscera procedure (format must be \"viscera-procedure\")",
                          {file, "/format", ""});
  }
  if (format_version(j) != 1)
    throw ValidationError("procedure version must be 1", {file, "/version", ""});
  ProcedureDefinition p;
  std::string member;
  try {
    member = "name";
    j.at(member).get_to(p.name);
    for (auto [key, value] : {std::pair{"title", &p.title},
                              {"procedure", &p.procedure},
                              {"description", &p.description}}) {
      member = key;
      if (j.contains(key)) j.at(key).get_to(*value);
    }
    member = "instrument";
    if (j.contains(member)) j.at(member).get_to(p.instrument);
    member = "duration_limit";
    p.duration_limit = j.value(member, p.duration_limit);
    member = "force_warning";
    p.force_warning = j.value(member, p.force_warning);
    member = "perforation_depth";
    p.perforation_depth = j.value(member, p.perforation_depth);
    member = "steps";
    j.at(member).get_to(p.steps);
  } catch (const nlohmann::json::exception& e) {
    throw ValidationError(std::string("cannot read: ") + e.what(), {file, "/" + member, ""});
  }
  if (!p.procedure.empty() &&
      std::find_if(std::begin(kProcedures), std::end(kProcedures),
                   [&p](const char* k) { return p.procedure == k; }) == std::end(kProcedures)) {
    throw ValidationError("unknown procedure \"" + p.procedure + "\"", {file, "/procedure", ""});
  }
  check_procedure(p, file);
  return p;
}

nlohmann::json procedure_to_json(const ProcedureDefinition& p) {
  return {{"format", "viscera-procedure"},
          {"version", 1},
          {"name", p.name},
          {"title", p.title},
          {"procedure", p.procedure},
          {"description", p.description},
          {"instrument", p.instrument},
          {"duration_limit", p.duration_limit},
          {"force_warning", p.force_warning},
          {"perforation_depth", p.perforation_depth},
          {"steps", p.steps}};
}

std::vector<std::string> procedure_definition_names() {
  std::vector<std::string> names;
  for (const auto& [name, procedure] : builtin_procedures())
    names.push_back(name);
  return names;
}

const ProcedureDefinition& procedure_definition(const std::string& name) {
  const auto& procedures = builtin_procedures();
  const auto it = procedures.find(name);
  if (it == procedures.end()) {
    std::string known;
    for (const auto& [n, p] : procedures)
      known += (known.empty() ? "" : ", ") + n;
    throw UsageError("unknown procedure \"" + name + "\" (known: " + known + ")");
  }
  return it->second;
}

void apply_procedure(SessionSpec& session, const ProcedureDefinition& procedure) {
  session.procedure_definition = procedure.name;
  session.instrument = procedure.instrument;
  session.steps = procedure.steps;
  session.duration_limit = procedure.duration_limit;
  session.force_warning = procedure.force_warning;
  session.perforation_depth = procedure.perforation_depth;
}

std::vector<const TaskSpec*> all_tasks(const SessionSpec& session) {
  std::vector<const TaskSpec*> tasks;
  for (const auto& task : session.tasks)
    tasks.push_back(&task);
  for (const auto& step : session.steps) {
    for (const auto& substep : step.substeps) {
      for (const auto& task : substep.tasks)
        tasks.push_back(&task);
    }
  }
  return tasks;
}

}  // namespace viscera::core
