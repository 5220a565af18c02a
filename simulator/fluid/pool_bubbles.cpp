#include "simulator/fluid/pool_bubbles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace viscera::sim::fluid {

namespace {

/// Pairs farther apart than this many touching distances do not interact.
constexpr double kCutoff = 2.5;

}  // namespace

PoolBubbles::PoolBubbles(PoolBubbleOptions options, std::uint64_t seed)
    : options_(options), rng_(seed) {
  const PoolBubbleOptions& o = options_;
  if (!(o.entrainment_speed > 0.0) || !(o.min_radius > 0.0) || !(o.max_radius >= o.min_radius) ||
      !(o.min_life > 0.0) || !(o.max_life >= o.min_life) || !(o.well_depth > 0.0) ||
      !(o.viscosity > 0.0) || o.capacity < 1 || !std::isfinite(o.max_radius) ||
      !std::isfinite(o.max_life) || !std::isfinite(o.well_depth) || !std::isfinite(o.viscosity))
    throw core::InputError(
        "pool bubbles: speeds, radii, lives and constants must be positive and finite, radii "
        "and lives ordered from least to most, and the capacity at least 1");
}

void PoolBubbles::drop_lands(const core::Vec3& point, const core::Vec3& velocity,
                             const FluidPool& pool) {
  if (velocity.dot(pool.down()) < options_.entrainment_speed) return;
  if (static_cast<int>(bubbles_.size()) >= options_.capacity) return;
  PoolBubble b;
  b.position = point;
  b.radius = rng_.uniform(options_.min_radius, options_.max_radius);
  b.life = rng_.uniform(options_.min_life, options_.max_life);
  bubbles_.push_back(b);
  ++trapped_;
}

void PoolBubbles::step(double dt, const FluidPool& pool, const PoolWaves& waves, bool sucking,
                       const core::Vec3& suction_tip, double suction_reach) {
  if (!(dt > 0.0)) return;
  const std::size_t before = bubbles_.size();
  const bool dry = pool.contents().total() <= 0.0;
  std::erase_if(bubbles_, [&](PoolBubble& b) {
    b.age += dt;
    return dry || b.age >= b.life ||
           (sucking && (b.position - suction_tip).norm() <= suction_reach + b.radius);
  });
  burst_ += static_cast<long long>(before - bubbles_.size());
  const core::Vec3 up = -pool.down();
  const auto across = [&](const core::Vec3& d) -> core::Vec3 { return d - d.dot(up) * up; };
  // Lennard-Jones pair forces across the surface, U = ε((r_m/r)¹² − 2 (r_m/r)⁶).
  forces_.assign(bubbles_.size(), core::Vec3::Zero());
  for (std::size_t a = 0; a < bubbles_.size(); ++a)
    for (std::size_t b = a + 1; b < bubbles_.size(); ++b) {
      const core::Vec3 d = across(bubbles_[b].position - bubbles_[a].position);
      const double touching = bubbles_[a].radius + bubbles_[b].radius;
      const double squared = d.squaredNorm(), cutoff = kCutoff * touching;
      if (squared >= cutoff * cutoff) continue;
      const double r = std::sqrt(squared);
      const double safe = std::max(r, 0.5 * touching);  // coincident births push apart
      const double s2 = (touching / safe) * (touching / safe), s6 = s2 * s2 * s2;
      const double push = 12.0 * options_.well_depth / safe * (s6 * s6 - s6);  // N, apart
      const core::Vec3 unit = r > 0.0 ? core::Vec3(d / r) : up.unitOrthogonal();
      forces_[a] -= push * unit;
      forces_[b] += push * unit;
    }
  // Overdamped (Stokes drag), capped; kept inside the rim and in the surface.
  const double rim = std::sqrt(pool.area() / std::numbers::pi);
  for (std::size_t k = 0; k < bubbles_.size(); ++k) {
    PoolBubble& b = bubbles_[k];
    core::Vec3 move = dt * forces_[k] / (6.0 * std::numbers::pi * options_.viscosity * b.radius);
    if (move.norm() > 0.1 * b.radius) move *= 0.1 * b.radius / move.norm();
    core::Vec3 flat = across(b.position + move - pool.floor());
    const double limit = std::max(0.0, rim - b.radius);
    if (flat.norm() > limit) flat *= limit / flat.norm();
    const core::Vec3 at = pool.floor() + flat;
    b.position = at + (pool.height() + waves.elevation(at)) * up;
  }
}

}  // namespace viscera::sim::fluid
