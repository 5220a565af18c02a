#include "simulator/physics/organ_motility.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/random.h"

namespace viscera::sim {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kContractionTime = 0.15;  ///< τ in s

/// (s/τ) e^{1 − s/τ}: 0 at the start, 1 at s = τ, falling after.
double contraction_shape(double s) {
  if (s <= 0.0) return 0.0;
  const double x = s / kContractionTime;
  return x * std::exp(1.0 - x);
}

}  // namespace

OrganMotility::OrganMotility(const core::MotilitySpec& spec, std::vector<core::Vec3> rest,
                             std::uint64_t seed)
    : spec_(spec), seed_(seed), rest_(std::move(rest)) {
  if (rest_.empty()) throw core::UsageError("organ motility needs at least one knot");
  if (!(spec.wave_speed > 0.0)) throw core::UsageError("motility wave speed must be positive");
  if (!(spec.wave_direction.norm() > 0.0))
    throw core::UsageError("motility wave direction must not be zero");
  const core::Vec3 direction = spec.wave_direction.normalized();

  centroid_ = core::Vec3::Zero();
  for (const auto& p : rest_)
    centroid_ += p;
  centroid_ /= static_cast<double>(rest_.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : rest_)
    covariance += (p - centroid_) * (p - centroid_).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  axis_ = solver.eigenvectors().col(2).normalized();  // largest eigenvalue last
  // A sign that does not depend on the solver: the axis points along +wave direction, or +z.
  const double sense = std::abs(axis_.dot(direction)) > 1e-9 ? axis_.dot(direction) : axis_.z();
  if (sense < 0.0) axis_ = -axis_;

  core::Rng rng(seed);
  const double spread = std::sqrt(std::max(0.0, spec.amplitude_variance));
  radial_.reserve(rest_.size());
  for (const auto& p : rest_) {
    const core::Vec3 offset = p - centroid_;
    core::Vec3 radial = offset - offset.dot(axis_) * axis_;
    radial_.push_back(radial.norm() > 1e-12 ? radial.normalized() : axis_.unitOrthogonal());
    along_.push_back(offset.dot(direction));
    const double sign = rng.uniform01() < 0.5 ? -1.0 : 1.0;
    amplitude_.push_back(spec.amplitude_mean + sign * rng.uniform01() * spread);
    frequency_.push_back(spec.frequency + spec.frequency_disturbance * rng.uniform01());
  }
}

double OrganMotility::contraction(double t) const {
  const double interval = spec_.contraction_interval_mean;
  if (!(interval > 0.0)) return 0.0;
  const double jitter_limit =
      std::min(0.4 * interval, std::sqrt(std::max(0.0, spec_.contraction_interval_variance)));
  // Contraction k starts at (k + 1)·interval + jitter_k; only the latest few can still act.
  const auto k_now = static_cast<std::int64_t>(std::floor(t / interval));
  double c = 0.0;
  for (std::int64_t k = std::max<std::int64_t>(0, k_now - 3); k <= k_now; ++k) {
    core::Rng rng = core::Rng::for_stream(seed_, static_cast<std::uint64_t>(k));
    const double start =
        static_cast<double>(k + 1) * interval + jitter_limit * rng.uniform(-1.0, 1.0);
    c = std::max(c, contraction_shape(t - start));
  }
  return c;
}

core::Vec3 OrganMotility::displacement(std::size_t i, double t) const {
  return displacement_with(i, t, contraction(t));
}

core::Vec3 OrganMotility::displacement_with(std::size_t i, double t, double contraction) const {
  const double phase = kTwoPi * frequency_[i] * (t - along_[i] / spec_.wave_speed);
  return amplitude_[i] * (std::sin(phase) * radial_[i] + 0.5 * std::cos(phase) * axis_) -
         contraction * spec_.amplitude_mean * radial_[i];
}

std::vector<core::Vec3> OrganMotility::positions(double t) const {
  const double c = contraction(t);
  std::vector<core::Vec3> out(rest_.size());
  for (std::size_t i = 0; i < rest_.size(); ++i)
    out[i] = rest_[i] + displacement_with(i, t, c);
  return out;
}

}  // namespace viscera::sim
