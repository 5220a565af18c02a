#include "simulator/fluid/irrigation_jet.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "simulator/fluid/jet_impact.h"

namespace viscera::sim::fluid {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw core::InputError("irrigation jet: " + what);
}
}  // namespace

IrrigationJet::IrrigationJet(JetOptions options) : options_(options) {
  const JetOptions& o = options_;
  require(o.rate > 0.0 && std::isfinite(o.rate), "the rate must be positive (m³/s)");
  require(o.speed > 0.0 && std::isfinite(o.speed), "the speed must be positive (m/s)");
  require(o.drop_volume > 0.0 && std::isfinite(o.drop_volume),
          "the drop volume must be positive (m³)");
  require(o.density > 0.0 && std::isfinite(o.density), "the density must be positive (kg/m³)");
  require(o.elasticity >= 0.0 && o.elasticity <= 1.0, "the elasticity ε must lie in [0, 1]");
  require(o.friction >= 0.0 && o.friction <= 1.0, "the friction µ must lie in [0, 1]");
  require(o.impact_scale > 0.0 && std::isfinite(o.impact_scale),
          "the impact scale k must be positive (1/m)");
  require(o.rest_speed >= 0.0 && std::isfinite(o.rest_speed), "the rest speed must be ≥ 0 (m/s)");
  require(o.max_bounces >= 0, "the bounce count must be ≥ 0");
  require(o.max_flight > 0.0 && std::isfinite(o.max_flight),
          "the longest flight must be positive (s)");
  require(o.offset >= 0.0 && std::isfinite(o.offset), "the surface offset must be ≥ 0 (m)");
  require(o.surface_tension > 0.0 && o.viscosity > 0.0 && o.splash_threshold > 0.0,
          "the surface tension, viscosity and splashing threshold must be positive");
}

double IrrigationJet::splash_number(int quarters, double v_normal) const {
  const JetOptions& o = options_;
  const double volume = o.drop_volume * (quarters / 4.0);
  const double d = std::cbrt(6.0 * volume / std::numbers::pi);
  const double weber = o.density * v_normal * v_normal * d / o.surface_tension;
  const double ohnesorge = o.viscosity / std::sqrt(o.density * o.surface_tension * d);
  return weber * std::pow(ohnesorge, -0.4);
}

double IrrigationJet::in_flight_volume() const {
  long long quarters = 0;
  for (const JetDrop& drop : drops_)
    quarters += drop.quarters;
  return static_cast<double>(quarters) * (0.25 * options_.drop_volume);
}

void IrrigationJet::emit(const core::Vec3& tip, const core::Vec3& direction, double dt) {
  if (!tip.allFinite() || !direction.allFinite() || direction.norm() == 0.0)
    throw core::InputError("irrigation jet: the tip and its direction must be finite, non-zero");
  if (!(dt >= 0.0)) throw core::InputError("irrigation jet: the time step must be ≥ 0 (s)");
  owed_ += options_.rate * dt;
  // A drop is owed once its volume is delivered, to rounding (10 ml/s in 1 ms steps: one each).
  const double whole = options_.drop_volume * (1.0 - 1e-9);
  const core::Vec3 velocity = options_.speed * direction.normalized();
  while (owed_ >= whole) {
    owed_ -= options_.drop_volume;
    drops_.push_back({tip, velocity, 0.0, 0, 4});
    ++emitted_;
  }
}

std::vector<JetImpact> IrrigationJet::step(double dt, const core::Vec3& gravity,
                                           const SurfaceQuery& surfaces, FluidPool& pool) {
  if (!(dt >= 0.0) || !gravity.allFinite())
    throw core::InputError("irrigation jet: the step and gravity must be finite, dt ≥ 0");
  std::vector<JetImpact> impacts;
  std::vector<JetDrop> thrown;  // by splashes, after the drops already flying
  std::size_t kept = 0;
  long long landed = 0;
  landings_.clear();
  for (std::size_t i = 0; i < drops_.size(); ++i) {
    JetDrop drop = drops_[i];
    const std::size_t before = thrown.size();
    if (move(drop, dt, gravity, surfaces, pool, impacts, thrown, landings_)) {
      landed += drop.quarters;
      continue;
    }
    if (thrown.size() > before) {
      ++splashes_;
      continue;
    }
    drops_[kept++] = drop;
  }
  drops_.resize(kept);
  drops_.insert(drops_.end(), thrown.begin(), thrown.end());
  landed_ += landed;
  pool.add_water(static_cast<double>(landed) * (0.25 * options_.drop_volume));
  return impacts;
}

bool IrrigationJet::move(JetDrop& drop, double dt, const core::Vec3& gravity,
                         const SurfaceQuery& surfaces, const FluidPool& pool,
                         std::vector<JetImpact>& impacts, std::vector<JetDrop>& thrown,
                         std::vector<PoolLanding>& landings) const {
  const core::Vec3 from = drop.position;
  const core::Vec3 to = from + dt * drop.velocity + 0.5 * dt * dt * gravity;
  drop.age += dt;
  const std::optional<SurfaceHit> hit = surfaces ? surfaces(from, to) : std::nullopt;
  // The pool's surface first when the drop reaches it before any tissue.
  const double depth_from = pool.depth(from), depth_to = pool.depth(to);
  if (depth_to >= 0.0) {
    const double at_pool = depth_from >= 0.0 ? 0.0 : -depth_from / (depth_to - depth_from);
    if (!hit || hit->fraction >= at_pool) {
      landings.push_back({from + at_pool * (to - from), drop.velocity + at_pool * dt * gravity,
                          0.25 * drop.quarters * options_.drop_volume});
      return true;
    }
  }
  if (!hit) {
    drop.position = to;
    drop.velocity += dt * gravity;
    return drop.age >= options_.max_flight;
  }
  // Velocity at the hit: the fraction of the step flown, under the same gravity.
  const core::Vec3 v_old = drop.velocity + hit->fraction * dt * gravity;
  core::Vec3 normal = hit->normal.normalized();
  if (normal.dot(v_old) > 0.0) normal = -normal;  // the side the drop came from
  const core::Vec3 v_new = rebound_velocity(v_old, normal, options_.elasticity, options_.friction);
  const core::Vec3 force =
      impact_force(drop_mass(drop.quarters), options_.impact_scale, v_old, v_new);
  if (force.squaredNorm() > 0.0)
    impacts.push_back({hit->body, hit->nodes, hit->weights, force, hit->point});
  drop.position = hit->point + options_.offset * normal;
  drop.velocity = v_new;
  ++drop.bounces;
  const double v_normal = std::abs(v_old.dot(normal));
  if (drop.quarters == 4 && splash_number(4, v_normal) > options_.splash_threshold) {
    // The crown throws four quarter drops sideways, 90° apart, at the rebound's normal speed.
    core::Vec3 side = v_old - v_old.dot(normal) * normal;
    if (side.norm() < 1e-12 * v_old.norm()) side = normal.unitOrthogonal();
    side.normalize();
    const core::Vec3 other = normal.cross(side);
    const double throw_speed = options_.elasticity * v_normal;
    for (int k = 0; k < 4; ++k) {
      const double angle = std::numbers::pi * (0.25 + 0.5 * k);
      JetDrop child = drop;
      child.quarters = 1;
      child.velocity = v_new + throw_speed * (std::cos(angle) * side + std::sin(angle) * other);
      thrown.push_back(child);
    }
    return false;
  }
  return v_new.norm() < options_.rest_speed || drop.bounces >= options_.max_bounces ||
         drop.age >= options_.max_flight;
}

}  // namespace viscera::sim::fluid
