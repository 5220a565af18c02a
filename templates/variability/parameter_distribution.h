#pragma once
/// Variability rules (issue 6): a distribution attached to a template parameter, drawn with the
/// project's RNG so a batch of patients is the same on every machine. The rule is data in the
/// scenario (core::VariabilityRule); its "arguments" by distribution:
///
/// | distribution       | arguments                                   | draws |
/// |--------------------|---------------------------------------------|-----------------------------|
/// | "fixed"            | {"value": v}                                | v | | "uniform"          |
/// {"min": a, "max": b}                        | uniform in [a, b)           | | "truncated-normal"
/// | {"mean": m, "stddev": s, "min": a, "max": b}| normal(m, s) kept in [a, b] | | "choice" |
/// {"values": [v…], "weights": [w…] (optional)}| one value, ∝ weight         | | "integer-range" |
/// {"min": a, "max": b}                        | whole number in [a, b]      |

#include <vector>

#include "core/random.h"
#include "core/scenario/scenario_parts.h"
#include "templates/template_catalog.h"

namespace viscera::templates {

/// Checks that `rule` is well formed and that everything it can draw lies inside the
/// parameter's range (and is whole for integer parameters). Throws core::UsageError naming the
/// parameter and the argument at fault.
void check_rule(const core::VariabilityRule& rule, const TemplateParameter& parameter);

/// One draw of `rule`. The rule must have passed check_rule.
double draw_rule(const core::VariabilityRule& rule, core::Rng& rng);

/// Checks every rule against the template: each names a parameter of it, at most once.
/// Throws core::UsageError.
void check_rules(const ScenarioTemplate& scenario_template,
                 const std::vector<core::VariabilityRule>& rules);

/// Values for every parameter of the template: a draw of its rule, or its default when no rule
/// names it. Parameters are drawn in the template's parameter order, so the same generator
/// state gives the same values.
ParameterValues draw_parameters(const ScenarioTemplate& scenario_template,
                                const std::vector<core::VariabilityRule>& rules, core::Rng& rng);

/// Convenience constructors for rules.
core::VariabilityRule fixed_rule(const std::string& parameter, double value);
core::VariabilityRule uniform_rule(const std::string& parameter, double min, double max);
core::VariabilityRule truncated_normal_rule(const std::string& parameter, double mean,
                                            double stddev, double min, double max);
core::VariabilityRule choice_rule(const std::string& parameter, const std::vector<double>& values,
                                  const std::vector<double>& weights = {});
core::VariabilityRule integer_range_rule(const std::string& parameter, int min, int max);

}  // namespace viscera::templates
