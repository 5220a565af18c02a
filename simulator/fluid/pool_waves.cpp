#include "simulator/fluid/pool_waves.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace viscera::sim::fluid {

namespace {

/// Columns shallower than this (m) carry no momentum worth a wave.
constexpr double kShallowest = 1e-4;

}  // namespace

PoolWaves::PoolWaves(const core::Vec3& floor, const core::Vec3& down, double area, int cells)
    : floor_(floor), n_(cells) {
  if (!down.allFinite() || down.norm() == 0.0)
    throw core::InputError("pool waves need the direction of gravity, but it is zero");
  if (!(area > 0.0) || !std::isfinite(area))
    throw core::InputError("pool waves need a positive pool area (m²), not " +
                           std::to_string(area));
  if (cells < 4)
    throw core::InputError("pool waves need at least 4 cells across the pool, not " +
                           std::to_string(cells));
  up_ = -down.normalized();
  u_ = up_.unitOrthogonal();
  v_ = up_.cross(u_);
  radius_ = std::sqrt(area / std::numbers::pi);
  dx_ = 2.0 * radius_ / n_;
  const auto count = static_cast<std::size_t>(n_ * n_);
  inside_.assign(count, 0);
  for (int j = 0; j < n_; ++j)
    for (int i = 0; i < n_; ++i) {
      const double u = -radius_ + (i + 0.5) * dx_, v = -radius_ + (j + 0.5) * dx_;
      if (u * u + v * v <= radius_ * radius_) {
        inside_[static_cast<std::size_t>(j * n_ + i)] = 1;
        ++inside_count_;
      }
    }
  eta_.assign(count, 0.0);
  rate_.assign(count, 0.0);
  laplacian_.assign(count, 0.0);
}

std::size_t PoolWaves::cell_at(double u, double v) const {
  // Clamped a cell inside the rim, its cell's centre lies within the disc.
  const double r = std::hypot(u, v), limit = std::max(0.0, radius_ - dx_);
  if (r > limit) {
    u *= limit / r;
    v *= limit / r;
  }
  const int i = std::clamp(static_cast<int>(std::floor((u + radius_) / dx_)), 0, n_ - 1);
  const int j = std::clamp(static_cast<int>(std::floor((v + radius_) / dx_)), 0, n_ - 1);
  return static_cast<std::size_t>(j * n_ + i);
}

void PoolWaves::spread(std::vector<double>& field, std::size_t c, double amount) const {
  const double share = amount / inside_count_;
  for (std::size_t k = 0; k < field.size(); ++k)
    if (inside_[k]) field[k] -= share;
  field[c] += amount;
}

void PoolWaves::drop_lands(const core::Vec3& point, const core::Vec3& velocity, double volume,
                           double depth) {
  if (!(volume > 0.0) || !point.allFinite() || !velocity.allFinite()) return;
  const core::Vec3 d = point - floor_;
  const std::size_t c = cell_at(d.dot(u_), d.dot(v_));
  const double cell_area = dx_ * dx_;
  still_ = false;
  spread(eta_, c, volume / cell_area);
  if (depth < kShallowest) return;
  const double falling = std::max(0.0, -velocity.dot(up_));  // m/s into the water
  spread(rate_, c, -volume * falling / (cell_area * depth));
}

void PoolWaves::step(double dt, double depth) {
  if (!(dt > 0.0) || still_) return;
  if (!(depth >= kShallowest)) {
    std::fill(eta_.begin(), eta_.end(), 0.0);
    std::fill(rate_.begin(), rate_.end(), 0.0);
    still_ = true;
    return;
  }
  const double c2 = kGravity * depth;
  const double stable = 0.9 * dx_ / std::sqrt(2.0 * c2);
  const int substeps = std::max(1, static_cast<int>(std::ceil(dt / stable)));
  const double h = dt / substeps, inverse_dx2 = 1.0 / (dx_ * dx_);
  for (int s = 0; s < substeps; ++s) {
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i < n_; ++i) {
        const auto c = static_cast<std::size_t>(j * n_ + i);
        if (!inside_[c]) continue;
        // Flux form with reflecting rims: a missing neighbour contributes nothing.
        double sum = 0.0;
        if (i > 0 && inside(i - 1, j)) sum += eta_[c - 1] - eta_[c];
        if (i + 1 < n_ && inside(i + 1, j)) sum += eta_[c + 1] - eta_[c];
        if (j > 0 && inside(i, j - 1)) sum += eta_[c - static_cast<std::size_t>(n_)] - eta_[c];
        if (j + 1 < n_ && inside(i, j + 1)) sum += eta_[c + static_cast<std::size_t>(n_)] - eta_[c];
        laplacian_[c] = sum * inverse_dx2;
      }
    for (std::size_t c = 0; c < eta_.size(); ++c) {
      if (!inside_[c]) continue;
      rate_[c] += h * (c2 * laplacian_[c] - kDamping * rate_[c]);
      eta_[c] += h * rate_[c];
    }
  }
}

double PoolWaves::elevation_at(double u, double v) const {
  const double fu = (u + radius_) / dx_ - 0.5, fv = (v + radius_) / dx_ - 0.5;
  const int i0 = static_cast<int>(std::floor(fu)), j0 = static_cast<int>(std::floor(fv));
  const double tu = fu - i0, tv = fv - j0;
  const double fallback = eta_[cell_at(u, v)];
  const auto at = [&](int i, int j) {
    if (i < 0 || j < 0 || i >= n_ || j >= n_ || !inside(i, j)) return fallback;
    return eta_[static_cast<std::size_t>(j * n_ + i)];
  };
  return (1.0 - tv) * ((1.0 - tu) * at(i0, j0) + tu * at(i0 + 1, j0)) +
         tv * ((1.0 - tu) * at(i0, j0 + 1) + tu * at(i0 + 1, j0 + 1));
}

double PoolWaves::elevation(const core::Vec3& point) const {
  const core::Vec3 d = point - floor_;
  return elevation_at(d.dot(u_), d.dot(v_));
}

double PoolWaves::displaced_volume() const {
  double sum = 0.0;
  for (std::size_t c = 0; c < eta_.size(); ++c)
    if (inside_[c]) sum += eta_[c];
  return sum * dx_ * dx_;
}

double PoolWaves::largest_elevation() const {
  double largest = 0.0;
  for (const double e : eta_)
    largest = std::max(largest, std::abs(e));
  return largest;
}

}  // namespace viscera::sim::fluid
