#include "simulator/fluid/blood_particles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "simulator/fluid/face_sampler.h"

namespace viscera::sim::fluid {

BloodParticles::BloodParticles(const BloodParticleSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(seed) {
  if (!(settings.particle_volume > 0.0) || !(settings.lifetime > 0.0) ||
      !(settings.emitter_time_constant > 0.0) || !(settings.spread >= 0.0))
    throw core::UsageError(
        "blood particles need a positive volume, lifetime and emitter time constant and a "
        "spread ≥ 0");
  position_.reserve(settings.capacity);
  emit_velocity_.reserve(settings.capacity);
  age_.reserve(settings.capacity);
  blood_.reserve(settings.capacity);
}

void BloodParticles::emit(const core::Vec3& site, const core::Vec3& normal, double speed,
                          double volume, const FlowGrid& grid, ConcentrationField& field) {
  if (!(volume > 0.0)) return;
  pending_ += volume;
  const double count = std::floor(pending_ / settings_.particle_volume);
  pending_ -= count * settings_.particle_volume;
  const core::Vec3 n = normal.normalized();
  // Any two unit vectors across the normal span the cone's base.
  const core::Vec3 u = n.unitOrthogonal();
  const core::Vec3 w = n.cross(u);
  const double cos_spread = std::cos(settings_.spread);
  for (double k = 0; k < count; k += 1.0) {
    emitted_ += settings_.particle_volume;
    if (age_.size() >= settings_.capacity) {
      release(grid, field, site, settings_.particle_volume);
      continue;
    }
    const double cos_theta = rng_.uniform(cos_spread, 1.0);
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const double phi = rng_.uniform(0.0, 2.0 * std::numbers::pi);
    const core::Vec3 direction =
        cos_theta * n + sin_theta * (std::cos(phi) * u + std::sin(phi) * w);
    position_.push_back(site);
    emit_velocity_.push_back(speed * direction);
    age_.push_back(0.0);
    blood_.push_back(settings_.particle_volume);
  }
}

void BloodParticles::advance(const FlowGrid& grid, const ArtificialVortices* vortices,
                             ConcentrationField& field, double time_step) {
  if (!(time_step > 0.0)) return;
  // Each particle gives the field its blood at a steady rate over its life.
  const double release_per_step = settings_.particle_volume * time_step / settings_.lifetime;
  const double inverse_h = 1.0 / grid.cell_size();
  const VelocitySampler sample(grid);  // the grid's strides taken once for every particle
  constexpr int kMaxSubsteps = 32;
  // First every particle moves (each on its own: in parallel, the same bits on any number of
  // threads), then each releases its blood into the field in order.
  const auto count = static_cast<std::ptrdiff_t>(age_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t n = 0; n < count; ++n) {
    const auto i = static_cast<std::size_t>(n);
    age_[i] += time_step;
    const double weight = std::exp(-age_[i] / settings_.emitter_time_constant);
    const auto velocity = [&](const core::Vec3& at) {
      const core::Vec3 flow =
          vortices ? core::Vec3(sample(at) + vortices->velocity(at)) : sample(at);
      return core::Vec3(weight * emit_velocity_[i] + (1.0 - weight) * flow);
    };
    // Sub-steps of at most one cell each, so a fast spurt meets the wall instead of jumping it;
    // a particle that would enter tissue stays where it is, its emitter's push spent on the wall.
    core::Vec3 v = velocity(position_[i]);
    const int substeps =
        std::clamp(static_cast<int>(std::ceil(v.norm() * time_step * inverse_h)), 1, kMaxSubsteps);
    const double dt = time_step / substeps;
    for (int s = 0; s < substeps; ++s) {
      if (s > 0) v = velocity(position_[i]);
      const core::Vec3 next = position_[i] + dt * v;
      const CellCoord cell = grid.cell_of(next);
      if (grid.contains(cell) && grid.cell(cell.i, cell.j, cell.k) == FlowCell::Solid) {
        emit_velocity_[i] = core::Vec3::Zero();
        break;
      }
      position_[i] = next;
    }
  }
  std::size_t i = 0;
  while (i < age_.size()) {
    const bool dies = age_[i] >= settings_.lifetime;
    const double given = dies ? blood_[i] : std::min(blood_[i], release_per_step);
    release(grid, field, position_[i], given);
    blood_[i] -= given;
    if (dies) {
      remove(i);  // the last particle, moved already, is released next
    } else {
      ++i;
    }
  }
}

double BloodParticles::carried_volume() const {
  double total = 0.0;
  for (const double b : blood_)
    total += b;
  return total;
}

void BloodParticles::release(const FlowGrid& grid, ConcentrationField& field,
                             const core::Vec3& point, double volume) {
  if (!(volume > 0.0)) return;
  double added = field.add_blood(grid, point, volume);
  // A particle the tissue or the sheath has moved over gives its blood to the fluid beside it.
  const double h = grid.cell_size();
  for (int n = 0; n < 6 && added == 0.0; ++n) {
    core::Vec3 beside = point;
    beside[n / 2] += (n % 2 == 0 ? -h : h);
    added = field.add_blood(grid, beside, volume);
  }
  released_ += added;
  lost_ += volume - added;
}

void BloodParticles::remove(std::size_t i) {
  const std::size_t last = age_.size() - 1;
  position_[i] = position_[last];
  emit_velocity_[i] = emit_velocity_[last];
  age_[i] = age_[last];
  blood_[i] = blood_[last];
  position_.pop_back();
  emit_velocity_.pop_back();
  age_.pop_back();
  blood_.pop_back();
}

}  // namespace viscera::sim::fluid
