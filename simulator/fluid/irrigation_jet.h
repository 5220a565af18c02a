#pragma once
/// The jet of a suction–irrigation cannula as a particle system (seed 001 §4.3 after Reeves
/// 1983; specs §4.8): "the initial velocity and amount of particles are calculated from real
/// data of surgical instruments for irrigation", the particles are "created while the
/// irrigation instrument is active" and move by Newton's laws under gravity; each one that hits
/// tissue pushes the hit knots (eq. 4, jet_impact.h) and rebounds (eq. 5); the ones that come
/// to rest gather in the pool (fluid_pool.h).
///
/// Real data (JetOptions): a 5 mm suction–irrigation cannula on a pressure bag at 300 mmHg
/// delivers about 10 ml/s (600 ml/min) through its 4 mm bore, so the jet leaves the tip at
/// 10 ml/s / (π · (2 mm)²) ≈ 0.8 m/s along the shaft. Each particle is a drop of 0.01 ml
/// (a 4 mm slug of jet 0.8 mm long, 10 mg of water): one drop per 1 ms step.
///
/// Motion per step of h s: x ← x + v h + ½ g h², v ← v + g h (explicit, and exact for the
/// constant gravity a drop feels in flight: drops do not interact with each other or the
/// gas). A step whose segment meets a tissue surface (the caller's SurfaceQuery: the session
/// casts it against bounding-volume hierarchies of the bodies' surfaces, the paper's
/// "hierarchical collision tests with bounding boxes") stops at the hit: the drop sits 0.1 mm
/// off the surface with its rebound velocity for the rest of the step. A drop joins the pool
///   - when it reaches the pool's surface (water into water: no rebound), or
///   - when a rebound leaves it slower than `rest_speed` or it has hit tissue `max_bounces`
///     times (it runs down the tissue to the pool: that path is not simulated), or
///   - after `max_flight` s in the air (a jet pointed up in zero gravity must land somewhere).
/// Splashing (seed 001 §4.3: "generating new particles after a particle collision"): a drop
/// whose impact passes the splashing threshold of Cossali, Coghe & Marengo (1997) for drops on
/// a wet surface, K = We · Oh^−0.4 > 2100 (We = ρ v_N² d / σ, Oh = µ / √(ρ σ d), d the drop's
/// diameter, v_N its normal speed), breaks into four drops of a quarter of its volume each: all
/// leave with its rebound velocity plus a sideways throw of the crown, ε |v_N| along four
/// directions 90° apart in the surface's plane (so their momentum is the rebound's). Split
/// drops do not split again. At the cannula's speeds a drop splashes only after a fall of
/// about 20 cm or more (K ≈ 490 at 1 m/s), so in the pelvis the jet rarely splashes.
/// Bubbles are not simulated.
///
/// Volume is conserved exactly in counts of quarter drops: emitted = in flight + joined the
/// pool.

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "core/math_types.h"
#include "simulator/fluid/fluid_pool.h"

namespace viscera::sim::fluid {

struct JetOptions {
  double rate = 10e-6;        ///< m³/s: 10 ml/s from a pressure bag at 300 mmHg
  double speed = 0.8;         ///< m/s at the tip: the rate through a 4 mm bore
  double drop_volume = 1e-8;  ///< m³ per particle (0.01 ml)
  double density = 1000.0;    ///< kg/m³, saline
  /// ε of eq. 5: water on wet tissue hardly bounces; most of its normal speed goes into
  /// spreading (a drop's coefficient of restitution on a wet surface is about 0.1–0.3).
  double elasticity = 0.2;
  /// µ of eq. 5: a film of water slides on wet serosa but drags; 30 % of the slide is lost.
  double friction = 0.3;
  /// k of eq. 4 in 1/m: 1/(2 d) for a drop stopped over d = 1 mm of tissue and water film.
  double impact_scale = 500.0;
  double rest_speed = 0.05;          ///< m/s below which a rebounding drop runs off to the pool
  int max_bounces = 3;               ///< hits after which a drop runs off to the pool
  double max_flight = 2.0;           ///< s in the air after which a drop is taken to the pool
  double offset = 1e-4;              ///< m off the surface a drop is put after a hit
  double surface_tension = 0.072;    ///< σ, N/m, saline at body temperature (≈ water)
  double viscosity = 0.7e-3;         ///< µ, Pa·s, saline at 37 °C
  double splash_threshold = 2100.0;  ///< K above which a drop splashes (Cossali et al. 1997)
};

/// One drop in flight.
struct JetDrop {
  core::Vec3 position = core::Vec3::Zero();  ///< m
  core::Vec3 velocity = core::Vec3::Zero();  ///< m/s
  double age = 0.0;                          ///< s since it left the tip
  int bounces = 0;                           ///< tissue hits so far
  /// Quarters of an emitted drop it holds: 4, or 1 for a drop a splash threw off.
  int quarters = 4;
};

/// Where a step's segment first meets a tissue surface.
struct SurfaceHit {
  double fraction = 1.0;                    ///< 0…1 along the segment
  core::Vec3 point = core::Vec3::Zero();    ///< m
  core::Vec3 normal = core::Vec3::UnitZ();  ///< unit, either orientation
  int body = -1;                            ///< the caller's body index
  std::array<int, 3> nodes{};               ///< the hit triangle's knots (the caller's numbers)
  core::Vec3 weights{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};  ///< barycentric of the point over them
};

/// The first surface the segment from → to meets, or nullopt.
using SurfaceQuery =
    std::function<std::optional<SurfaceHit>(const core::Vec3& from, const core::Vec3& to)>;

/// The push of one drop on the knots of the triangle it hit: `force` N at the hit point,
/// shared over `nodes` by `weights` (barycentric: the three shares add up to the force and
/// act at the point).
struct JetImpact {
  int body = -1;
  std::array<int, 3> nodes{};
  core::Vec3 weights = core::Vec3::Zero();
  core::Vec3 force = core::Vec3::Zero();  ///< N
  core::Vec3 point = core::Vec3::Zero();  ///< m
};

/// A drop that fell into the pool's surface (not one that ran down the tissue to it).
struct PoolLanding {
  core::Vec3 point = core::Vec3::Zero();     ///< m, on the pool's surface
  core::Vec3 velocity = core::Vec3::Zero();  ///< m/s as it met the water
  double volume = 0.0;                       ///< m³
};

class IrrigationJet {
 public:
  /// Throws core::InputError for a rate, speed, drop volume, density, impact scale or flight
  /// time that is not positive, ε or µ outside [0, 1], or a negative rest speed or bounce count.
  explicit IrrigationJet(JetOptions options = {});

  /// The irrigation valve open for `dt` s with the tip at `tip` (m) pointing along `direction`
  /// (unit): emits the whole drops the rate delivers in that time, the remainder carried to
  /// the next call.
  void emit(const core::Vec3& tip, const core::Vec3& direction, double dt);

  /// Moves every drop through `dt` s under `gravity` (m/s²), in emission order: hits against
  /// `surfaces` give impacts and rebounds; drops that come to rest join `pool`. Returns the
  /// step's impacts in drop order.
  std::vector<JetImpact> step(double dt, const core::Vec3& gravity, const SurfaceQuery& surfaces,
                              FluidPool& pool);

  const std::vector<JetDrop>& drops() const { return drops_; }
  const JetOptions& options() const { return options_; }
  /// kg of an emitted drop (`quarters` 4) or of a splash's drop (1).
  double drop_mass(int quarters = 4) const {
    return options_.density * options_.drop_volume * (quarters / 4.0);
  }
  /// K = We · Oh^−0.4 of a drop of `quarters` hitting a surface at normal speed `v_normal` m/s.
  double splash_number(int quarters, double v_normal) const;
  /// m³ emitted so far / in flight now / handed to the pool so far.
  double emitted_volume() const { return static_cast<double>(emitted_) * options_.drop_volume; }
  double in_flight_volume() const;
  double landed_volume() const {
    return static_cast<double>(landed_) * (0.25 * options_.drop_volume);
  }
  int splashes() const { return splashes_; }  ///< impacts that broke a drop up
  /// The drops the last step() let fall into the pool's surface, in drop order.
  const std::vector<PoolLanding>& last_landings() const { return landings_; }

 private:
  /// Advances one drop; true when it joined the pool (a fall into its surface also in
  /// `landings`). A splash puts the drops it throws off in
  /// `thrown` (the drop itself then joins nothing and is replaced by them).
  bool move(JetDrop& drop, double dt, const core::Vec3& gravity, const SurfaceQuery& surfaces,
            const FluidPool& pool, std::vector<JetImpact>& impacts, std::vector<JetDrop>& thrown,
            std::vector<PoolLanding>& landings) const;

  JetOptions options_;
  std::vector<JetDrop> drops_;
  double owed_ = 0.0;      ///< m³ delivered but not yet a whole drop
  long long emitted_ = 0;  ///< drops
  long long landed_ = 0;   ///< quarter drops
  int splashes_ = 0;
  std::vector<PoolLanding> landings_;
};

}  // namespace viscera::sim::fluid
