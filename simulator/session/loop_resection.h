#pragma once
/// The resectoscope's loop electrode in a session (seed 000 §5 and §5.1; issue 17 §1, §4, §5).
///
/// While the cutting pedal is down (InstrumentState::electrode) the loop's sweep is sampled:
/// one pose whenever the loop has moved a tenth of its radius or turned 5° since the last.
/// When the pedal comes up, the sweep is cut into every pathology body it traverses, once
/// ("object meshes are decomposed only once they have been completely traversed", §5.1): the
/// swept surface (cutting::swept_loop_surface) goes to the hybrid cut (cutting::hybrid_cut), the
/// world takes the new topology (World::topology_changed, which rebuilds every cache) and the
/// fragments that lost every anchor — the nodes bound to the wall, or held fixed — are chips:
/// excised tissue that moves freely, falls and meets the wall through body contact. A sweep
/// released with the loop still inside a body does not cut that body (the seed's rule); the
/// report counts it. Pieces cut off below a volume bound are not chips but debris: they leave
/// the body (retired_tissue.h) and the distension flow carries them as particles.
///
/// Decisions where the seed is silent: the loop hangs from the tip on the side the angled optics
/// look towards (InstrumentState::up), in the plane across the shaft, so it is in view; the cut
/// reaches pathology bodies only (polyps, myomas), not the wall they grow on, whose cutting
/// needs the perforation rules of issue 17 §5. Chips stay in their body's node range.

#include <functional>
#include <string>
#include <vector>

#include "simulator/cutting/cut_surface.h"
#include "simulator/cutting/fragments.h"
#include "simulator/cutting/hybrid_cut.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/session_report.h"
#include "simulator/session/visible_surfaces.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// Pieces cut off below 1 mm³ (a sphere of 1.24 mm) are debris, not chips: a few tets at most,
/// too small to be simulated as bodies of their own or to be seen as more than a shred.
inline constexpr double kDebrisVolume = 1e-9;  ///< m³

/// The loop of a standard 26 Fr resectoscope: a half ring of 2.5 mm radius (a 5 mm wide cut).
cutting::LoopElectrode standard_resection_loop();

/// The loop frame at the instrument's pose: origin on the shaft, `loop_extension` in front of the
/// tip, local z along the shaft, the loop hanging (local −y) towards `up`.
cutting::LoopPose loop_pose(const InstrumentState& state);

/// A chip: a fragment of a cut body that lost every anchor (local node indices, ascending).
struct Chip {
  int body = 0;
  std::vector<int> nodes;
  double rest_volume = 0.0;  ///< m³
};

class LoopResection {
 public:
  /// `bodies`: indices of the world bodies the loop may cut; `names` their names for the report.
  LoopResection(const World& world, std::vector<int> bodies, cutting::LoopElectrode loop);

  /// The summary before any cut: every cuttable body with its rest volume.
  void begin(const World& world, CuttingSummary& summary) const;

  /// After every physics step: follows the pedal and the loop at `state`; when the pedal comes
  /// up, cuts and records the cut in `summary` and its events in `events` (at `time` s).
  void follow(const InstrumentState& state, World& world, double time, CuttingSummary& summary,
              std::vector<SessionEvent>& events);

  /// Called for each body a cut changed, after the world took its new topology and chips() was
  /// renewed, with the world body's index and the session time in s (the session starts
  /// bleeding there, issue 18 §3).
  using CutObserver =
      std::function<void(int body, const cutting::TopologyChange& change, double time)>;
  void on_cut(CutObserver observer) { observer_ = std::move(observer); }
  /// Where a debris shred goes: its centre (m) and the radius of the sphere of its volume (m).
  using DebrisSink = std::function<void(const core::Vec3& centre, double radius)>;
  /// Pieces cut off with a rest volume below `volume` m³ become debris: they leave their body
  /// after the cut observer has seen the cut, and `sink` receives each. Without a sink (no flow
  /// to carry them) every piece cut off stays a chip.
  void shed_debris_below(double volume, DebrisSink sink) {
    debris_volume_ = volume;
    debris_sink_ = std::move(sink);
  }
  /// Cuts go through `surfaces` (null: the tets alone), so the bodies' visible surfaces follow.
  void cut_visible_surfaces(VisibleSurfaces* surfaces) { visible_ = surfaces; }

  /// The chips of every body cut so far (a body's list is renewed at each of its cuts), less
  /// those retrieved.
  const std::vector<Chip>& chips() const { return chips_; }
  /// Takes chips()[`chip`] out of the patient through the cervix (chip_retrieval.h): it leaves
  /// its body's mesh (retired_tissue.h) and counts as retrieved, its volume still resected.
  void retrieve(std::size_t chip, World& world, double time, CuttingSummary& summary,
                std::vector<SessionEvent>& events);
  /// True while the pedal is down.
  bool sweeping() const { return sweeping_; }
  /// The surface the last sweep swept (CuttingSummary::sweeps counts them), m.
  const cutting::CutSurface& last_sweep() const { return last_sweep_; }
  /// True when cuttable body `body` was held at the start and every hold it had was cut.
  bool lost_every_hold(const World& world, int body) const;
  const cutting::LoopElectrode& loop() const { return loop_; }
  /// The world bodies the loop may cut.
  const std::vector<int>& bodies() const { return bodies_; }

 private:
  void cut(World& world, double time, CuttingSummary& summary, std::vector<SessionEvent>& events);
  void record_pose(const InstrumentState& state);
  /// Retires `shreds` (fragments of body `body`, cuttable body `k`) as debris.
  void shed(World& world, int body, std::size_t k, const std::vector<cutting::Fragment>& shreds,
            BodyResection& resection);
  /// Takes `fragments` of body `body` out of its mesh.
  void remove(World& world, int body, const std::vector<cutting::Fragment>& fragments);

  std::vector<int> bodies_;
  std::vector<double> initial_volume_;       ///< m³ rest volume of each cuttable body at the start
  std::vector<std::uint8_t> held_at_start_;  ///< per cuttable body: held by another at the start
  std::vector<double> removed_volume_;       ///< m³ of each cuttable body shed or retrieved so far
  cutting::LoopElectrode loop_;
  cutting::HybridCutOptions options_;
  bool sweeping_ = false;
  std::vector<cutting::LoopPose> sweep_;
  CutObserver observer_;
  double debris_volume_ = 0.0;
  DebrisSink debris_sink_;
  VisibleSurfaces* visible_ = nullptr;
  std::vector<Chip> chips_;
  cutting::CutSurface last_sweep_;
};

}  // namespace viscera::sim
