#pragma once
/// The fluid balance of a distended uterine cavity (hydrometra), lumped into one pressure
/// (seed 000 §1.1.2–1.1.3: in- and outflow through the hysteroscope's valves, pump pressure,
/// fluid overload by absorption; §11: "the amount of distension media used" is a metric).
///
/// The cavity is one compliant chamber at pressure P (Pa) with volume V = V₀ + C·P. The pump
/// feeds it through the inflow channel, the outflow channel drains it, and above the absorption
/// threshold fluid leaves through the tubal ostia and open vessels (intravasation):
///
///   C dP/dt = u_in G_in (P_pump − P) − u_out G_out (P − P_drain) − G_abs max(0, P − P_abs)
///
/// with valve openings u ∈ [0, 1] and channel conductances G (m³ s⁻¹ Pa⁻¹) from Hagen–Poiseuille,
/// G = π r⁴ / (8 μ L). Within a step the valves are constant, so the equation is linear in each
/// regime (below or above P_abs); step() solves it exactly, splitting the step where P crosses
/// P_abs, and integrates the three flows exactly. Hence the balance
/// used − drained − absorbed = C (P_end − P_start) holds to rounding for any step length.
///
/// Opened vessels (issue 18 §3–4) add one linear path each between the cavity and the blood
/// behind the opening, G_v (P_v − P): below the vessel's pressure blood enters the cavity
/// (bleeding), above it distension fluid enters the circulation (intravasation). One path in both
/// directions is the trade-off of seed 000 §1.1.4 — raising the pressure stops a small bleed and
/// "potentially aggravates the previously mentioned intravasation problems". The seeds state no
/// intravasation model; this one makes it grow with the pressure above the vessel's and, through
/// G_v, with the opened vessel's size. The step splits wherever P crosses a vessel pressure, so
/// bled and intravasated volumes are exact too, and
/// used + bled − drained − absorbed − intravasated = C (P_end − P_start).

#include <vector>

#include "core/scenario/scenario_parts.h"

namespace viscera::sim {

/// Physical constants of the instrument's channels and of the cavity.
struct DistensionChannels {
  /// m³ s⁻¹ Pa⁻¹, inflow channel fully open: radius 0.6 mm, 0.35 m of channel and tubing,
  /// saline at body temperature (μ = 0.7 mPa·s) — about 170 ml/min into an empty cavity at
  /// 100 mmHg, the range of continuous-flow hysteroscopes.
  double inflow_conductance = poiseuille_conductance(0.6e-3, 0.35, 0.7e-3);
  /// m³ s⁻¹ Pa⁻¹, outflow channel fully open: radius 0.55 mm, same length.
  double outflow_conductance = poiseuille_conductance(0.55e-3, 0.35, 0.7e-3);
  /// m³/Pa: the cavity grows by about 6 ml between 0 and 100 mmHg.
  double cavity_compliance = 6.0e-6 / 13332.0;
  /// m³, volume of the collapsed cavity.
  double resting_volume = 2.0e-6;
  /// m³ s⁻¹ Pa⁻¹ of tubal spill and intravasation above the threshold: about 20 ml/min at
  /// 50 mmHg above it.
  double absorption_conductance = 20.0e-6 / 60.0 / 6666.0;
  /// Pa above which fluid is absorbed: 75 mmHg, about the mean arterial pressure.
  double absorption_threshold = 10000.0;

  /// π r⁴ / (8 μ L): the laminar conductance of a pipe of radius `radius` m and length `length` m
  /// for a fluid of dynamic viscosity `viscosity` Pa·s.
  static double poiseuille_conductance(double radius, double length, double viscosity);
};

/// An opened vessel (or a cut's capillary bed) as the cavity sees it: a conductance between the
/// cavity and the blood pressure behind the opening.
struct VesselOpening {
  double conductance = 0.0;  ///< m³ s⁻¹ Pa⁻¹, ≥ 0 (0: closed by a clip or coagulation)
  double pressure = 0.0;     ///< Pa, the blood's pressure behind the opening

  bool operator==(const VesselOpening&) const = default;
};

/// Volumes exchanged so far, m³, and the pressure history's extremes.
struct FluidTotals {
  double used = 0.0;                  ///< delivered by the pump through the inflow channel
  double drained = 0.0;               ///< collected through the outflow channel
  double absorbed = 0.0;              ///< lost through the ostia and the tissue
  double bled = 0.0;                  ///< blood that entered the cavity through opened vessels
  double intravasated = 0.0;          ///< fluid that entered the circulation through them
  double max_pressure = 0.0;          ///< Pa
  double time_above_threshold = 0.0;  ///< s with the pressure above the absorption threshold
  double pressure_time = 0.0;         ///< Pa·s, ∫P dt over the steps taken
  double duration = 0.0;              ///< s stepped
  /// Pa, the time-averaged cavity pressure (0 before the first step).
  double mean_pressure() const { return duration > 0.0 ? pressure_time / duration : 0.0; }
  /// The clinical fluid deficit: used − drained, what the fluid-management system shows (the
  /// drained fluid carries the blood that entered, so it is short of the patient's uptake by the
  /// blood loss while the cavity holds the rest).
  double deficit() const { return used - drained; }
  /// Distension fluid the patient took up: absorbed through tissue and ostia plus intravasated.
  double uptake() const { return absorbed + intravasated; }
};

/// The cavity's fluid state, advanced step by step.
class DistensionBalance {
 public:
  /// Pump and drain pressures and the overload limit from the scenario; throws core::InputError
  /// naming /scenario/fluid when a pressure is negative or not finite, or a channel constant is
  /// not positive.
  explicit DistensionBalance(const core::FluidSpec& fluid, DistensionChannels channels = {});

  /// Advances `dt` s with the valve openings (clamped to [0, 1]) and the vessel openings held
  /// over the step.
  void step(double inflow_opening, double outflow_opening, double dt);

  /// Replaces the opened vessels (the bleeding model's current set). Throws core::UsageError for
  /// a negative or non-finite conductance or pressure.
  void set_openings(std::vector<VesselOpening> openings);
  const std::vector<VesselOpening>& openings() const { return openings_; }
  /// Per opening, the volume that passed it in the last step, m³: positive for blood that
  /// entered the cavity, negative for fluid that left into the circulation.
  const std::vector<double>& last_step_volumes() const { return last_step_volumes_; }

  double pressure() const { return pressure_; }  ///< Pa
  /// m³ of fluid in the cavity, V₀ + C·P.
  double cavity_volume() const;
  const FluidTotals& totals() const { return totals_; }
  /// Whether the deficit has reached the scenario's overload volume (a complication).
  bool overloaded() const { return totals_.deficit() >= fluid_.overload_volume; }
  const core::FluidSpec& fluid() const { return fluid_; }
  const DistensionChannels& channels() const { return channels_; }

 private:
  struct Regime;
  /// The linear regime in force at the current pressure for these valve conductances.
  Regime regime(double g_in, double g_out) const;
  /// Solves `regime` exactly over `dt` (no pressure of an opening or of the absorption threshold
  /// crossed inside it), moves the pressure there and adds the flows.
  void advance(const Regime& regime, double dt);

  core::FluidSpec fluid_;
  DistensionChannels channels_;
  double pressure_ = 0.0;
  FluidTotals totals_;
  std::vector<VesselOpening> openings_;
  std::vector<double> last_step_volumes_;
};

}  // namespace viscera::sim
