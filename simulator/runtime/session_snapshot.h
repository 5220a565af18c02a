#pragma once
/// What the view shows of a running session at one physics step (issue 16 item 3): the
/// positions of every body, the instrument and the overlay's numbers. The physics thread fills
/// one and hands it to the render thread through a TripleBuffer, so the view never reads the
/// SessionRunner while it steps.

#include <memory>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/surgical_smoke.h"
#include "simulator/session/visible_surfaces.h"

namespace viscera::sim {

class SessionRunner;

/// One body's nodes, by the body's (scenario object's) name.
struct BodyPositions {
  std::string name;
  std::vector<core::Vec3> positions;  ///< m
  /// Per node, 1 where the bipolar forceps coagulated the tissue (issue 19 §3); empty when no
  /// node of the body is coagulated.
  std::vector<float> coagulated;
  /// The body's visible surface as cut so far (VisibleSurfaces), or null while it is uncut;
  /// shared, immutable, so the copy is a pointer.
  std::shared_ptr<const CutVisibleSurface> cut_surface;
};

/// A session as the view draws it.
struct SessionSnapshot {
  long long steps = 0;
  double time = 0.0;  ///< s simulated
  std::vector<BodyPositions> bodies;
  InstrumentState instrument;
  double optics_angle = 0.0;                         ///< °
  core::Vec3 instrument_force = core::Vec3::Zero();  ///< N on the instrument
  double time_limit = 0.0;                           ///< s
  double force_warning = 0.0;                        ///< N, 0: none
  double surface_seen = 0.0;                         ///< fraction 0…1
  std::string step;                                  ///< procedure step under way, or ""
  std::string ended;                                 ///< end reason once finished, or ""
  /// Blood in the cavity's flow (issue 18 §5): each particle's position (m) and stage (age over
  /// life, 0…1), and the blood's mean extinction along the optics' line of sight, 1/m (the
  /// lens pass's haze).
  std::vector<core::Vec3> blood;
  std::vector<float> blood_stage;
  double haze_density = 0.0;
  /// Air bubbles in the cavity's flow, or on the laparoscopy's pool: each one's position (m) and
  /// its radius within the bubbles' range (0 smallest … 1 largest).
  std::vector<core::Vec3> bubbles;
  std::vector<float> bubble_size;
  /// Tissue debris of the resection in the cavity's flow: each shred's position (m) and its
  /// radius over the debris bound's (0…1).
  std::vector<core::Vec3> debris;
  std::vector<float> debris_size;
  /// The irrigation jet's drops in flight (issue 19 §3): positions (m) and age over the
  /// longest flight (0…1).
  std::vector<core::Vec3> irrigation_drops;
  std::vector<float> irrigation_drop_age;
  /// The pool's surface (issue 19 §3): its centre (m), up (unit) and radius (m; 0: no pool);
  /// its blood is pool_blood_fraction.
  core::Vec3 pool_centre = core::Vec3::Zero();
  core::Vec3 pool_up = core::Vec3::UnitZ();
  double pool_radius = 0.0;
  /// The waves on it (fluid::PoolWaves): elevations in m at the vertices of a polar mesh over
  /// the disc — the centre, then kPoolRings rings of kPoolSides vertices from the centre out,
  /// ring k at k/kPoolRings of the radius, vertex s at 2π s/kPoolSides from up.unitOrthogonal()
  /// towards up × that. Empty without a pool.
  static constexpr int kPoolRings = 8, kPoolSides = 64;
  std::vector<float> pool_waves;
  /// Smoke of coagulation (issue 19 §4): camera-facing puffs, and the steam on the lens (0…1).
  std::vector<SmokeBillboard> smoke;
  double lens_fog = 0.0;
  bool tools = false;  ///< the instrument carries laparoscopic tools
  /// The pool of irrigation fluid and blood (suction_irrigation.h), m³, and its blood over all
  /// its fluid (0…1).
  double pool_volume = 0.0;
  double pool_blood_fraction = 0.0;
};

/// Fills `out` from `runner` at its current step, reusing out's storage (no allocation once
/// the sizes are known).
void capture_snapshot(const SessionRunner& runner, SessionSnapshot& out);

}  // namespace viscera::sim
