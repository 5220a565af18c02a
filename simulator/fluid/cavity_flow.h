#pragma once
/// The distension flow of a session (issue 18 §2–3, seed 000 §2.2 and §6): stable fluids on the
/// cavity's voxel grid, labelled from the current wall, pathologies and instrument, with the
/// sheath's jet, its outflow holes and the superimposed vortices; the blood of the bleeding
/// sources leaves as particles that the flow carries and that release it into a concentration
/// field, which the flow advects and which clouds the optics' line of sight.
///
/// Decided where the seed is silent:
/// - Grid: the cavity wall's box plus `margin` cells (room to distend), `resolution` cells along
///   its longest side: 28 by default, about 1.1 mm cells in a 3 cm cavity (seed 000 §2.2 used
///   40³ over its scene; a session's grid covers the cavity alone). One flow step every
///   `interval` s of session time, 25 Hz by default (the seed's solver ran at 26 Hz), particles
///   on the same clock.
/// - Relabelling: the wall, every pathology surface and the sheath are labelled again once any
///   of them has moved `relabel_motion` cells since it was last labelled, or has been cut. The
///   grid's frame never changes, so velocities and blood stay where they were; blood in cells
///   the wall closes over is pushed to their open neighbours (ConcentrationField::settle), and
///   a cell never holds more blood than its volume (ConcentrationField::spill).
/// - Sheath: cells within the shaft's radius of its axis behind the tip are solid at rest; the
///   last cell length of it is the inflow, its velocity along the axis scaled so that its net
///   flux into the cavity is the pump's inflow of the step (DistensionBalance). The outflow
///   holes are open cells (pressure 0) beside the shaft 5–15 mm behind the tip, where the
///   continuous-flow sheath draws fluid back (beside its last 5 mm while only the tip is in the
///   cavity). The grid's volume is fixed (the hydrometra, not
///   the flow, distends the cavity), so what the jet brings leaves there.
/// - Air bubbles (air_bubbles.h) enter at the inflow cells while the pump delivers into the
///   cavity, are carried with each flow step and rise against gravity (CavityInputs::up).
/// - Tissue debris (suspended_particles.h): shreds of a resection too small to be chips enter
///   where the session cut them off, are carried with each flow step and settle against gravity
///   (tissue, about 1050 kg/m³, is 50 kg/m³ denser than saline); the outflow holes draw them out
///   through the sheath.
/// - Clouding: Beer–Lambert along the line of sight, T = exp(−k ∫ c ds) over the first
///   `view_depth` m, c the blood fraction, k = `extinction`: 1 % of blood over 2 cm gives
///   T = e⁻¹. The view counts as obscured while T < `obscured_transmission`.

#include <cstdint>
#include <span>
#include <vector>

#include "simulator/fluid/air_bubbles.h"
#include "simulator/fluid/artificial_vortices.h"
#include "simulator/fluid/blood_particles.h"
#include "simulator/fluid/concentration_field.h"
#include "simulator/fluid/stable_fluids.h"
#include "simulator/fluid/suspended_particles.h"

namespace viscera::sim::fluid {

struct CavityFlowSettings {
  int resolution = 28;          ///< cells along the longest side of the cavity's box
  int margin = 3;               ///< cells around the cavity wall's box
  double interval = 0.04;       ///< s of session time between flow steps
  double relabel_motion = 0.5;  ///< cells a surface may move before the grid is labelled again
  double sheath_radius = 2e-3;  ///< m, half the shaft's diameter
  double view_depth = 0.02;     ///< m of the line of sight the blood clouds
  double extinction = 5000.0;   ///< k, 1/m per unit blood fraction
  double obscured_transmission = 0.5;  ///< T below which the view is obscured
  FlowSettings flow;                   ///< the solver's (its time step is `interval`)
  BloodParticleSettings particles;
  AirBubbleSettings bubbles;
  /// Tissue debris: 50 kg/m³ denser than saline, at most 500 shreds at once.
  SuspensionSettings debris{1.0e-3, -50.0, 9.81, 0.25, 500};
  VortexSettings vortices;
};

/// A closed surface in the cavity (a pathology, a chip) at its current positions, m.
struct CavityObstacle {
  std::span<const core::Vec3> positions;
  const std::vector<core::Triangle>* triangles = nullptr;
};

/// Blood entering the cavity at a bleeding site in one physics step.
struct BloodRelease {
  core::Vec3 site = core::Vec3::Zero();     ///< m
  core::Vec3 normal = core::Vec3::UnitZ();  ///< unit, out of the tissue
  double speed = 0.0;                       ///< m/s at the opening
  double volume = 0.0;                      ///< m³
};

/// A shred of tissue entering the cavity where a cut took it off.
struct DebrisRelease {
  core::Vec3 position = core::Vec3::Zero();  ///< m
  double radius = 0.0;                       ///< m, of the sphere of its volume
};

/// What the session hands the flow at one physics step.
struct CavityInputs {
  std::span<const core::Vec3> wall;  ///< the wall surface's current positions, m
  std::vector<CavityObstacle> obstacles;
  bool obstacles_cut = false;  ///< an obstacle's surface changed its triangles this step
  bool sheath = false;  ///< an instrument's sheath is in the scene (it acts once its tip is in a
                        ///< fluid cell of the wall's labelling)
  core::Vec3 tip = core::Vec3::Zero();    ///< m
  core::Vec3 axis = core::Vec3::UnitZ();  ///< unit, handle towards tip
  double inflow_rate = 0.0;               ///< m³/s the pump delivers this step
  core::Vec3 up = core::Vec3::Zero();     ///< unit, against gravity (zero: bubbles do not rise)
  std::vector<BloodRelease> blood;
  std::vector<DebrisRelease> debris;
};

class CavityFlow {
 public:
  /// The cavity of the wall surface `wall`/`triangles` whose vertices `cavity_marks` marks 1.
  /// Throws what label_cavity throws; core::UsageError for bad settings.
  CavityFlow(std::span<const core::Vec3> wall, const std::vector<core::Triangle>& triangles,
             const std::vector<double>& cavity_marks, const CavityFlowSettings& settings,
             std::uint64_t seed);

  /// Advances `dt` s: releases the step's blood as particles and, once `interval` s have
  /// gathered, relabels what moved and takes one flow step, moving particles and blood with it.
  /// Throws core::SimulationError when the flow's velocity is no longer finite, and
  /// core::UsageError when a flow step is due and `inputs.wall` does not have the wall's size.
  void advance(double dt, const CavityInputs& inputs);
  /// True when advancing `dt` s takes a flow step (and needs the surfaces in its inputs).
  bool step_due(double dt) const { return gathered_ + dt >= settings_.interval * (1.0 - 1e-9); }

  /// Share of light that reaches `eye` (m) along `direction` (unit) through the blood in front
  /// of it, 0…1.
  double view_transmission(const core::Vec3& eye, const core::Vec3& direction) const;
  bool obscured(const core::Vec3& eye, const core::Vec3& direction) const {
    return view_transmission(eye, direction) < settings_.obscured_transmission;
  }

  const FlowGrid& grid() const { return grid_; }
  const ConcentrationField& blood() const { return blood_; }
  const BloodParticles& particles() const { return particles_; }
  const AirBubbles& bubbles() const { return bubbles_; }
  const SuspendedParticles& debris() const { return debris_; }
  const ArtificialVortices& vortices() const { return vortices_; }
  const CavityFlowSettings& settings() const { return settings_; }
  /// Blood released so far, m³: in particles, in the field, drained or lost; equals the sum of
  /// the releases handed in.
  double released_blood() const { return released_; }
  long long flow_steps() const { return flow_steps_; }
  long long relabellings() const { return relabellings_; }
  const FlowStepReport& last_step() const { return last_step_; }

 private:
  /// Labels the wall and the obstacles when they moved or were cut, then the sheath.
  void relabel(const CavityInputs& inputs);
  void label_sheath(const CavityInputs& inputs, bool in_cavity);
  /// Closes the pockets a pathology or the sheath cut off from the outflow
  /// (close_stranded_pockets), whose pressure nothing would fix.
  void close_stranded();
  /// The point lies in a fluid cell of the wall's and obstacles' labelling.
  bool in_tissue_fluid(const core::Vec3& point) const;
  /// Sets the inflow cells' velocity so their net flux is `inflow` m³/s.
  void drive_inflow(const core::Vec3& axis, double inflow);

  CavityFlowSettings settings_;
  std::vector<core::Triangle> wall_triangles_;
  FlowGrid grid_;
  FlowSolver solver_;
  ConcentrationField blood_;
  BloodParticles particles_;
  AirBubbles bubbles_;
  SuspendedParticles debris_;
  ArtificialVortices vortices_;
  /// Positions at the last labelling, to measure motion against.
  std::vector<core::Vec3> wall_labelled_;
  std::vector<std::vector<core::Vec3>> obstacles_labelled_;
  /// The labels of the wall and obstacles alone, and the instrument's cells over them.
  std::vector<FlowCell> tissue_labels_;
  std::vector<int> inflow_cells_, sheath_cells_;
  core::Vec3 sheath_tip_ = core::Vec3::Constant(1e9), sheath_axis_ = core::Vec3::Zero();
  bool sheath_labelled_ = false;
  double gathered_ = 0.0, inflow_volume_ = 0.0, released_ = 0.0;
  long long flow_steps_ = 0, relabellings_ = 0;
  FlowStepReport last_step_;
};

}  // namespace viscera::sim::fluid
