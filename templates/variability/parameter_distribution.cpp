#include "templates/variability/parameter_distribution.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"

namespace viscera::templates {
namespace {

double number(const core::VariabilityRule& rule, const char* key) {
  const auto it = rule.arguments.find(key);
  if (it == rule.arguments.end() || !it->is_number() || !std::isfinite(it->get<double>())) {
    throw core::UsageError("variability rule for \"" + rule.parameter + "\" (" + rule.distribution +
                           ") needs a number \"" + key + "\"");
  }
  return it->get<double>();
}

std::vector<double> numbers(const core::VariabilityRule& rule, const char* key, bool required) {
  const auto it = rule.arguments.find(key);
  if (it == rule.arguments.end()) {
    if (required) {
      throw core::UsageError("variability rule for \"" + rule.parameter + "\" needs \"" + key +
                             "\"");
    }
    return {};
  }
  std::vector<double> values;
  if (it->is_array()) {
    for (const auto& v : *it) {
      if (v.is_number() && std::isfinite(v.get<double>()))
        values.push_back(v.get<double>());
      else
        values.clear(), values.push_back(std::nan(""));
    }
  }
  if (!it->is_array() || values.empty() ||
      std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); })) {
    throw core::UsageError("variability rule for \"" + rule.parameter + "\": \"" + key +
                           "\" must be a non-empty array of numbers");
  }
  return values;
}

void check_in_range(const core::VariabilityRule& rule, const TemplateParameter& p, double value,
                    const char* what) {
  if (value < p.minimum || value > p.maximum) {
    throw core::UsageError("variability rule for \"" + rule.parameter + "\": " + what + " " +
                           std::to_string(value) + " is outside the parameter's range [" +
                           std::to_string(p.minimum) + ", " + std::to_string(p.maximum) + "] " +
                           p.unit);
  }
  if (p.integer && value != std::floor(value)) {
    throw core::UsageError("variability rule for \"" + rule.parameter + "\": " + what +
                           " must be a whole number");
  }
}

}  // namespace

void check_rule(const core::VariabilityRule& rule, const TemplateParameter& p) {
  const std::string& d = rule.distribution;
  if (d == "fixed") {
    check_in_range(rule, p, number(rule, "value"), "value");
  } else if (d == "uniform" || d == "integer-range" || d == "truncated-normal") {
    const double lo = number(rule, "min"), hi = number(rule, "max");
    if (!(lo < hi) && !(d == "integer-range" && lo == hi)) {
      throw core::UsageError("variability rule for \"" + rule.parameter +
                             "\": min must be below max");
    }
    check_in_range(rule, p, lo, "min");
    check_in_range(rule, p, hi, "max");
    if (d == "uniform" && p.integer) {
      throw core::UsageError("variability rule for \"" + rule.parameter +
                             "\": a whole-number parameter takes integer-range, not uniform");
    }
    if (d == "truncated-normal") {
      if (p.integer) {
        throw core::UsageError("variability rule for \"" + rule.parameter +
                               "\": a whole-number parameter cannot be normally distributed");
      }
      if (!(number(rule, "stddev") > 0.0)) {
        throw core::UsageError("variability rule for \"" + rule.parameter +
                               "\": stddev must be positive");
      }
      (void)number(rule, "mean");
    }
  } else if (d == "choice") {
    const auto values = numbers(rule, "values", true);
    for (const double v : values)
      check_in_range(rule, p, v, "choice");
    const auto weights = numbers(rule, "weights", false);
    if (!weights.empty()) {
      double total = 0.0;
      for (const double w : weights) {
        if (w < 0.0)
          throw core::UsageError("variability rule for \"" + rule.parameter +
                                 "\": negative weight");
        total += w;
      }
      if (weights.size() != values.size() || !(total > 0.0)) {
        throw core::UsageError("variability rule for \"" + rule.parameter +
                               "\": one non-negative weight per value, not all zero");
      }
    }
  } else {
    throw core::UsageError("variability rule for \"" + rule.parameter +
                           "\": unknown distribution \"" + d +
                           "\" (fixed, uniform, truncated-normal, choice, integer-range)");
  }
}

double draw_rule(const core::VariabilityRule& rule, core::Rng& rng) {
  const std::string& d = rule.distribution;
  if (d == "fixed") return number(rule, "value");
  if (d == "uniform") return rng.uniform(number(rule, "min"), number(rule, "max"));
  if (d == "integer-range") {
    return static_cast<double>(rng.uniform_int(static_cast<std::int64_t>(number(rule, "min")),
                                               static_cast<std::int64_t>(number(rule, "max"))));
  }
  if (d == "truncated-normal") {
    return rng.truncated_normal(number(rule, "mean"), number(rule, "stddev"), number(rule, "min"),
                                number(rule, "max"));
  }
  const auto values = numbers(rule, "values", true);
  auto weights = numbers(rule, "weights", false);
  if (weights.empty()) weights.assign(values.size(), 1.0);
  double total = 0.0;
  for (const double w : weights)
    total += w;
  double u = rng.uniform(0.0, total);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (u < weights[i]) return values[i];
    u -= weights[i];
  }
  return values.back();  // u rounded onto the total
}

void check_rules(const ScenarioTemplate& scenario_template,
                 const std::vector<core::VariabilityRule>& rules) {
  const auto parameters = scenario_template.parameters();
  std::set<std::string> seen;
  for (const auto& rule : rules) {
    const auto it =
        std::find_if(parameters.begin(), parameters.end(),
                     [&](const TemplateParameter& p) { return p.name == rule.parameter; });
    if (it == parameters.end()) {
      throw core::UsageError("variability rule names \"" + rule.parameter +
                             "\", which template \"" + scenario_template.name() +
                             "\" does not have");
    }
    if (!seen.insert(rule.parameter).second) {
      throw core::UsageError("two variability rules for \"" + rule.parameter + "\"");
    }
    check_rule(rule, *it);
  }
}

ParameterValues draw_parameters(const ScenarioTemplate& scenario_template,
                                const std::vector<core::VariabilityRule>& rules, core::Rng& rng) {
  ParameterValues values;
  for (const auto& p : scenario_template.parameters()) {
    const auto rule = std::find_if(rules.begin(), rules.end(), [&](const core::VariabilityRule& r) {
      return r.parameter == p.name;
    });
    values[p.name] = rule == rules.end() ? p.default_value : draw_rule(*rule, rng);
  }
  return values;
}

core::VariabilityRule fixed_rule(const std::string& parameter, double value) {
  return {parameter, "fixed", {{"value", value}}};
}
core::VariabilityRule uniform_rule(const std::string& parameter, double min, double max) {
  return {parameter, "uniform", {{"min", min}, {"max", max}}};
}
core::VariabilityRule truncated_normal_rule(const std::string& parameter, double mean,
                                            double stddev, double min, double max) {
  return {parameter,
          "truncated-normal",
          {{"mean", mean}, {"stddev", stddev}, {"min", min}, {"max", max}}};
}
core::VariabilityRule choice_rule(const std::string& parameter, const std::vector<double>& values,
                                  const std::vector<double>& weights) {
  core::VariabilityRule rule{parameter, "choice", {{"values", values}}};
  if (!weights.empty()) rule.arguments["weights"] = weights;
  return rule;
}
core::VariabilityRule integer_range_rule(const std::string& parameter, int min, int max) {
  return {parameter, "integer-range", {{"min", min}, {"max", max}}};
}

}  // namespace viscera::templates
