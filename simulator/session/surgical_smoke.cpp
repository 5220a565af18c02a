#include "simulator/session/surgical_smoke.h"

#include <algorithm>
#include <cmath>

namespace viscera::sim {

namespace {
constexpr double kFadeIn = 0.2;  ///< s a puff takes to reach its opacity
constexpr double kGoldenAngle = 2.399963229728653;
}  // namespace

SurgicalSmoke::SurgicalSmoke(const SmokeOptions& options) : options_(options) {}

SmokeBillboard SurgicalSmoke::billboard(const Puff& p) const {
  const double age = std::max(0.0, time_ - p.born);
  const double f = std::clamp(age / options_.life, 0.0, 1.0);
  // Two directions across the rise.
  core::Vec3 e1 = p.up.cross(core::Vec3::UnitX());
  if (e1.norm() < 1e-6) e1 = p.up.cross(core::Vec3::UnitY());
  e1.normalize();
  const core::Vec3 e2 = p.up.cross(e1);
  const double phase = kGoldenAngle * p.index;
  const double w = options_.sway_frequency;
  const double grow = std::min(1.0, age / 1.0);  // the column is thin where it leaves the tissue
  SmokeBillboard b;
  b.centre = p.origin + (options_.rise_speed * age) * p.up +
             (options_.sway * grow) *
                 (std::sin(w * age + phase) * e1 + std::sin(0.7 * w * age + 2.0 * phase) * e2);
  b.radius = options_.birth_radius + f * (options_.death_radius - options_.birth_radius);
  b.opacity = options_.birth_opacity * std::min(1.0, age / kFadeIn) * (1.0 - f);
  b.index = p.index;
  return b;
}

void SurgicalSmoke::step(double time, double dt, const std::optional<core::Vec3>& coagulating_at,
                         const core::Vec3& up, const core::Vec3& lens) {
  time_ = time;
  if (std::erase_if(puffs_, [&](const Puff& p) { return time - p.born >= options_.life; }) > 0)
    puffs_changed_ = true;
  if (coagulating_at && time >= next_puff_ - 1e-12) {
    puffs_.push_back({*coagulating_at, up, time, emitted_++});
    next_puff_ = time + options_.puff_interval;
    puffs_changed_ = true;
  }
  // The lens fogs near hot tissue and in smoke, and clears by itself.
  const bool near_heat = coagulating_at && (*coagulating_at - lens).norm() <= options_.lens_reach;
  const std::vector<SmokeBillboard> now = billboards();
  const double steam =
      (near_heat ? options_.fog_rate : 0.0) + options_.fog_rate * stacked_opacity(now, lens);
  fog_ += dt * steam * (1.0 - fog_);
  fog_ *= std::exp(-dt / options_.lens_clear_time);
  peak_fog_ = std::max(peak_fog_, fog_);
  // The densest point is O(n²) in the puffs: looked for again only when they change or a puff
  // interval has passed.
  if (puffs_changed_ || time >= smoky_checked_at_ + options_.puff_interval - 1e-12) {
    double densest = 0.0;
    for (const SmokeBillboard& b : now)
      densest = std::max(densest, stacked_opacity(now, b.centre));
    smoky_ = densest > options_.visible_opacity;
    smoky_checked_at_ = time;
    puffs_changed_ = false;
  }
  if (smoky_) smoke_time_ += dt;
}

int SurgicalSmoke::suck(const core::Vec3& tip, double radius, double time) {
  time_ = time;
  const auto before = puffs_.size();
  std::erase_if(puffs_,
                [&](const Puff& p) { return (billboard(p).centre - tip).norm() <= radius; });
  if (puffs_.size() != before) puffs_changed_ = true;
  return static_cast<int>(before - puffs_.size());
}

std::vector<SmokeBillboard> SurgicalSmoke::billboards() const {
  std::vector<SmokeBillboard> out;
  out.reserve(puffs_.size());
  for (const Puff& p : puffs_)
    out.push_back(billboard(p));
  return out;
}

double SurgicalSmoke::stacked_opacity(const std::vector<SmokeBillboard>& puffs,
                                      const core::Vec3& point) {
  double clear = 1.0;
  for (const SmokeBillboard& b : puffs)
    if ((b.centre - point).squaredNorm() <= b.radius * b.radius) clear *= 1.0 - b.opacity;
  return 1.0 - clear;
}

double SurgicalSmoke::opacity_at(const core::Vec3& point) const {
  return stacked_opacity(billboards(), point);
}

}  // namespace viscera::sim
