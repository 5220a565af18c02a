#pragma once
/// Variants of an arbitrary scenario (issue 9 §6): a scenario that no template built — e.g. an
/// organ meshed from an image volume with a pathology, texture and vessels added in the studio —
/// varies by a random smooth deformation of the whole scene (smooth_deformation.h; one field for
/// every object, so nested surfaces stay nested and disjoint ones disjoint) and by re-drawn
/// pathology sizes. Patient validation (validation/patient_validation.h) decides afterwards
/// whether a draw is a valid patient; this module only draws.
///
/// What moves: the surface vertices and body nodes of every object whose shape is its geometry
/// (body kind none, tet mesh, mass-spring), pathology positions, vessel segments (radii kept),
/// landmarks and their normals. Objects whose shape comes from a spec (cell-agent sheets,
/// urethra lattices) stay as they are. Then each pathology object is scaled about its
/// attachment (the mean of its nodes paired to its host) by size'/size, size' drawn uniformly
/// in size·[1 − spread, 1 + spread]. Tet bodies get their lumped masses recomputed from their
/// materials' densities, embeddings are rebuilt, normals recomputed.

#include <nlohmann/json.hpp>

#include "core/random.h"
#include "core/scenario/scenario.h"

namespace viscera::templates {

/// How much a scenario varies. Lengths relative to the scene's bounding-box diagonal D.
struct ScenarioVariation {
  int centres = 6;                     ///< Gaussian centres of the deformation field
  double amplitude_fraction = 0.03;    ///< standard deviation of each weight component, × D
  double width_fraction = 0.3;         ///< Gaussian width σ, × D
  double max_lipschitz = 0.5;          ///< bound on |∇d| (< 1 keeps the map injective)
  double pathology_size_spread = 0.2;  ///< relative half-range of the re-drawn sizes, in [0, 1)
};

/// One draw: the varied scenario and what was drawn, as
/// {"lipschitz_bound", "diagonal" (m), "pathology_sizes": {id: {"from", "to"} (m)}}.
struct ScenarioDraw {
  core::Scenario scenario;
  nlohmann::json drawn = nlohmann::json::object();
};

/// Draws one variant of `scenario` from `rng` (field first, then pathology sizes in scenario
/// order). The same scenario and generator state give the same variant. Throws
/// core::UsageError for out-of-range options, core::InputError when the scenario has no
/// geometry to vary.
ScenarioDraw vary_scenario(const core::Scenario& scenario, core::Rng& rng,
                           const ScenarioVariation& variation = {});

}  // namespace viscera::templates
