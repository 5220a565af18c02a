#pragma once
/// The bleeding sources of a session (issue 18 §3; seed 000 §6.2: "a bleeding source is
/// considered as an emitter, which creates noninteracting particles during the period of
/// bleeding"). A cut adds one source per authored vessel it opens (opened_vessels.h) and one
/// capillary ooze over its whole cut surface. Each source is a path between the cavity and the
/// blood behind it (a VesselOpening of the distension balance), so the balance decides how much
/// bleeds in a step and when the cavity pressure passes the vessel pressure and stops it.
///
/// A source stops for good (seed 000 §6.2 "it stops after a given time; however, it can also be
/// affected by coagulation procedures or pressure increase"):
/// - coagulated: the electrode's tip within its radius of the site;
/// - clipped: a clip between the tree's root and the opening (seed 001 §5.1.2; vessels only);
/// - clotted: capillary ooze decays as exp(−t/τ) and counts as stopped once below 1 % of its
///   opening rate. Named vessels do not clot by themselves.
/// Pressure stops a source only while the cavity stays above the vessel's pressure.

#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/scenario/scenario_parts.h"
#include "simulator/fluid/distension_balance.h"
#include "simulator/fluid/opened_vessels.h"

namespace viscera::sim::fluid {

enum class BleedingStop { Bleeding, Coagulated, Clipped, Clotted };

/// One source: where it is on its body and how freely it bleeds.
struct BleedingSource {
  bool capillary = false;      ///< ooze over a cut surface, not a named vessel
  std::string vessel_tree;     ///< the tree's id (vessel sources)
  int segment = -1;            ///< in that tree (vessel sources)
  double along = 0.0;          ///< of the opening on it, 0 proximal … 1 distal (vessel sources)
  std::vector<int> path;       ///< the segment's root path (vessel sources)
  double radius = 0.0;         ///< m, vessel radius (vessel sources)
  int level = 0;               ///< bifurcations from the tree's root (vessel sources)
  double area = 0.0;           ///< m² of cut surface (capillary sources)
  int body = 0;                ///< the caller's index of the body the site lies on
  std::array<int, 3> nodes{};  ///< the body's nodes around the site
  core::Vec3 barycentric{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};  ///< of the site over those nodes
  double opened_at = 0.0;                                   ///< s, session time of the cut
  double conductance = 0.0;                                 ///< m³ s⁻¹ Pa⁻¹ when opened
  double pressure = 0.0;                                    ///< Pa behind the opening
  /// A pulsing artery (seed 001 §5.1.2: the cut spurts in time with the pulse): the pressure
  /// behind the opening swings about its mean as P (1 + a cos(2π (t − delay) / period)), peaking
  /// as each beat's wave reaches the opening `delay` s after the beat. period 0: steady.
  double pulse_period = 0.0;     ///< s, 60 / heart rate
  double pulse_delay = 0.0;      ///< s, the wave's travel from the root to the opening
  double pulse_amplitude = 0.0;  ///< a, pulse pressure over twice the mean
  BleedingStop stop = BleedingStop::Bleeding;
  double stopped_at = -1.0;   ///< s, when `stop` was set
  double bled = 0.0;          ///< m³ of blood it let into the cavity so far
  double intravasated = 0.0;  ///< m³ of fluid it let into the circulation so far
};

class BleedingSources {
 public:
  explicit BleedingSources(BleedingPhysiology physiology = {});

  /// Registers a cut at session time `time` s on body `body`: `triangles` are the cut's new
  /// surface triangles over the body's rest `nodes` (m; the frame the trees were authored in).
  /// Every segment of `trees` the cut opens becomes a vessel source; the cut surface (half the
  /// triangles' area: both sides of the cut are given) becomes one capillary source at the
  /// centre of its largest triangle. Returns the number of vessel sources added.
  int add_cut(int body, std::span<const core::VesselTree> trees, std::span<const core::Vec3> nodes,
              std::span<const core::Triangle> triangles, double time);

  /// The openings the distension balance sees at `time` s, one per source in order (a stopped
  /// source has conductance 0); marks ooze that has clotted.
  std::vector<VesselOpening> openings(double time);

  /// Books the balance's last step: `volumes` (DistensionBalance::last_step_volumes, one per
  /// source) split into blood in and fluid out per source.
  void record_step(std::span<const double> volumes);

  /// Stops every bleeding source whose site lies within `radius` m of `tip` (m), with the site
  /// positions computed by the caller (site_position) in source order. Returns how many.
  int coagulate(const core::Vec3& tip, double radius, std::span<const core::Vec3> sites,
                double time);

  /// Stops every vessel source of `vessel_tree` whose root path runs through `segment` (a clip
  /// between the root and the cut). Returns how many.
  int clip(const std::string& vessel_tree, int segment, double time);
  /// A clip closed at `rest_point` (m, in the frame `tree` was authored in: its host's rest
  /// frame) on body `body`, at session time `time` s. It stops every bleeding vessel source of
  /// `tree` on that body whose blood passes it on the way from the tree's root to the opening
  /// (seed 001 §5.1.2): the clip lies within `reach` m of the wall of a segment on the source's
  /// root path and, on the opened segment itself, proximal to the opening. A clip beyond the
  /// opening, or on another branch, stops nothing. Returns how many sources it stopped.
  int clip_at(int body, const core::VesselTree& tree, const core::Vec3& rest_point, double reach,
              double time);
  /// Makes source `index` pulse (BleedingSource::pulse_period, s; delay, s; amplitude, 0…1).
  void set_pulse(std::size_t index, double period, double delay, double amplitude);

  const std::vector<BleedingSource>& sources() const { return sources_; }
  const BleedingPhysiology& physiology() const { return physiology_; }

 private:
  void stop(BleedingSource& source, BleedingStop why, double time);
  /// Stops, as clipped at `time` s, every bleeding vessel source of `vessel_tree` that
  /// `clipped` picks. Returns how many.
  int clip_where(const std::string& vessel_tree, double time,
                 const std::function<bool(const BleedingSource&)>& clipped);

  BleedingPhysiology physiology_;
  std::vector<BleedingSource> sources_;
};

/// The site of `source` over its body's current node positions (m).
core::Vec3 site_position(const BleedingSource& source, std::span<const core::Vec3> positions);

}  // namespace viscera::sim::fluid
