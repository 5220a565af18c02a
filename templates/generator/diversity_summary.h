#pragma once
/// The diversity summary of a batch (issue 6 §5): how the drawn parameters spread, and how far
/// apart the patients' organs are.
///
/// Shape distance between patients i and j: the symmetric mean closest-point distance between
/// their primary organs' surfaces, d(i, j) = ½ (mean over a ∈ A of min_b |a − b| + mean over
/// b ∈ B of min_a |a − b|), with A and B up to 500 evenly strided vertices of each surface
/// tested against all vertices of the other, in m, in the template's own frame (templates
/// place every patient in the same anatomical frame, so no registration is applied). 0 means
/// identical vertex sets.

#include <filesystem>
#include <nlohmann/json.hpp>

#include "templates/template_catalog.h"

namespace viscera::templates {

/// Per-parameter histograms of `records` (index records with "parameters") for every parameter
/// that a rule of the batch varies: count, mean, standard deviation, min, max, bin edges and
/// counts — one bin per whole number for integer parameters spanning ≤ 20 values, otherwise 10
/// equal bins over the template's [minimum, maximum].
nlohmann::json parameter_histograms(const ScenarioTemplate& scenario_template,
                                    const std::vector<core::VariabilityRule>& rules,
                                    const nlohmann::json& records);

/// Pairwise shape distances between the primary organs (record "organ") of the packages in
/// `folder` (record "package"): every pair when there are at most 1,000, otherwise each patient
/// against the next ⌈1000 / N⌉ cyclically. Returns the measure's description, unit, pair count,
/// min, mean, median, max, the closest pair and the number of identical pairs. Throws
/// core::InputError when a surface cannot be read.
nlohmann::json shape_distances(const nlohmann::json& records, const std::filesystem::path& folder);

}  // namespace viscera::templates
