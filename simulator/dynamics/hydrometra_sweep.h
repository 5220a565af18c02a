#pragma once
/// The authoring step of the hydrometra (seed 000 §2.1): "offline computations … to obtain the
/// response of the tissue model to the fluid pressure", "the organ model deformations are
/// obtained for 100 different pressure settings". Where the seed used a commercial FE package
/// with a hyper-elastic law, Viscera solves the same quasi-static problem with the energies the
/// session simulates (the Teschner distance, area and volume terms with each wall layer's
/// material, seed 000 §3) and its implicit solver, so the stored shapes are equilibria of the
/// very model that deforms about them at run time.
///
/// Decisions (the seed leaves range, spacing and tolerance open, seed-specs.md §3.1):
/// - Range: 0 to 20 kPa (150 mmHg), the upper end of the pump pressures of operative
///   hysteroscopy; 100 states uniformly spaced (202.02 Pa ≈ 1.5 mmHg apart), state 0 at 0 Pa
///   is the rest shape exactly (zero displacement). A wall that has no equilibrium below
///   20 kPa — Teschner energies do not stiffen with strain, so a soft wall balloons past a
///   limit pressure that scales with its stiffness, or yields before — gets its 100 states
///   evenly up to 90 % of the last elastic equilibrium before it (the sweep runs again over that
///   range, and logs a warning); at run time higher pressures clamp to that state.
/// - Load: the uniform pressure as a follower traction on the cavity-marked faces, P × area ×
///   normal shared by their corners (dynamics/cavity_pressure.h).
/// - Boundary conditions: the body's fixed nodes stay where they are — the template's
///   "vertices near the cervix are fixed" (seed 000 §2.1); everything else is free.
/// - Solver: per state, warm-started from the previous one extrapolated along the last secant
///   (kept only when it leaves less force), steps of backward Euler (dynamics/backward_euler.h)
///   of h = 1 s with the velocity reset to zero before each (so inertia only regularises
///   Newton's method: h² K/M ≈ 10⁷ for the wall; 2 Newton iterations of at most 60 CG
///   iterations to 1e-2, an inexact Newton), the follower load refreshed between steps, until
///   the largest nodal force residual |f_internal + f_pressure| of the free nodes is below
///   `relative_residual` × the largest nodal pressure load (1e-3), at most `max_iterations`
///   (20) steps a state. The wall's limit point is the first state that does not get there or
///   whose largest nodal movement per pascal is 10 × the first state's (lost 90 % of its
///   stiffness: it balloons) or that stretches a tet edge beyond its material's plastic yield
///   (a session would then give the wall a permanent set and, at the tearing strain, tear it).

#include <map>
#include <string>

#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::sim {

struct HydrometraSweepSettings {
  double max_pressure = 20000.0;  ///< Pa (150 mmHg)
  int states = 100;  ///< pressures k · max_pressure / (states − 1), k = 0 … states − 1
  double relative_residual = 1e-3;  ///< of the largest nodal pressure load at that pressure
  int max_iterations = 20;          ///< backward Euler steps per state at most
  /// A wall that gives way below max_pressure gets its states up to this fraction of the last
  /// equilibrium found (near its limit point the wall has no stiffness left: slow to converge
  /// and no use to a session).
  double limit_fraction = 0.9;
  /// The wall balloons (its limit point) once a state's largest nodal movement per pascal
  /// exceeds this multiple of the first state's: it has lost 90 % of its stiffness.
  double max_softening = 10.0;
  double pseudo_step = 1.0;    ///< s, h of the quasi-static steps
  int newton_iterations = 2;   ///< per backward Euler step at most
  int cg_iterations = 60;      ///< per Newton iteration at most
  double cg_tolerance = 1e-2;  ///< relative residual of each linear solve (inexact Newton)
};

/// The hydrometra states of `object` (a tet body whose surface marks a "cavity") with the
/// materials of its scenario. Throws core::UsageError for an object without cavity or tets or
/// bad settings, core::InputError for unknown materials, core::CancelledError when cancelled.
/// A wall that holds no pressure beyond its first states keeps the equilibria it reached (at
/// the least its rest shape, one state at 0 Pa), with a warning: a patient is never refused
/// for its hydrometra.
core::HydrometraStates sweep_hydrometra(const core::SceneObject& object,
                                        const std::map<std::string, core::Material>& materials,
                                        const HydrometraSweepSettings& settings = {},
                                        core::Progress& progress = core::Progress::none());

/// The pipeline step of `viscera new`, `viscera generate` and the studio's template dialog: when
/// the scenario has distension fluid, fills SceneObject::hydrometra of every tet-body organ
/// whose surface marks a cavity. Returns how many objects got states.
int add_hydrometra_states(core::Scenario& scenario,
                          core::Progress& progress = core::Progress::none());

}  // namespace viscera::sim
