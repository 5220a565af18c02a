#pragma once
/// The dynamic check of a generated patient (issue 6 §3): one simulated second, at the
/// scenario's own step and with its own bodies, must stay finite and bounded. Part of the
/// generator library because it runs the simulator (viscera_sim), which the template library
/// may not link (DESIGN.md §2).

#include "core/scenario/scenario.h"
#include "templates/validation/patient_validation.h"

namespace viscera::templates {

/// Bounds of the simulated second.
struct SimulationBounds {
  double duration = 1.0;  ///< s simulated
  /// No node may move further from its rest position than this fraction of its body's bounding
  /// diagonal: a free-resting patient only settles, so a larger motion is an instability.
  double max_displacement_fraction = 0.25;
  /// m/s: no node may move faster (tissue under its own weight moves at cm/s).
  double max_speed = 5.0;
  /// m: every free node starts displaced by a deterministic random offset of up to this much
  /// per axis (the velocity is zero). A patient at rest with no gravity (hysteroscopy: the uterus
  /// is held all round in the pelvis) would otherwise never move, and an unstable body would
  /// pass; a stable body rings down, an unstable one grows without bound.
  double perturbation = 1e-4;
};

/// Perturbs and then steps every body of `scenario`'s sim::World — tet and mass-spring bodies
/// (Teschner or KisMo) and cell-agent tissues — for bounds.duration seconds with no
/// instrument, checking positions every 10 steps. Measures: steps, substeps, max_displacement (m),
/// max_speed (m/s), final kinetic_energy (J). Never throws for a bad patient: a non-finite or
/// unbounded state or a simulator error is a failed check named "simulation".
ValidationCheck simulate_one_second(const core::Scenario& scenario,
                                    const SimulationBounds& bounds = {});

}  // namespace viscera::templates
