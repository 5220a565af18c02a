#include "simulator/physics/stable_step.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/error.h"

namespace viscera::sim {
namespace {

/// SplitMix64 (Steele, Lea & Flood 2014): a fixed, portable start vector for the iteration.
double start_component(std::uint64_t index) {
  std::uint64_t z = index * 0x9E3779B97F4A7C15ULL + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53 * 2.0 - 1.0;
}

double norm(std::span<const core::Vec3> x) {
  double sum = 0.0;
  for (const auto& v : x)
    sum += v.squaredNorm();
  return std::sqrt(sum);
}

}  // namespace

void RankOneSystem::add_term(std::span<const int> nodes, std::span<const core::Vec3> gradient,
                             double k) {
  if (nodes.size() != gradient.size())
    throw core::UsageError("a rank-one term needs one gradient per node");
  if (!(k > 0.0)) return;  // nothing to add (and a negative k would break semi-definiteness)
  if (first_.empty()) first_.push_back(0);
  nodes_.insert(nodes_.end(), nodes.begin(), nodes.end());
  gradients_.insert(gradients_.end(), gradient.begin(), gradient.end());
  coefficient_.push_back(k);
  first_.push_back(nodes_.size());
}

void RankOneSystem::multiply(std::span<const core::Vec3> x, std::span<core::Vec3> y) const {
  for (std::size_t n = 0; n < diagonal_.size(); ++n)
    y[n] = diagonal_[n] * x[n];
  for (std::size_t t = 0; t < coefficient_.size(); ++t) {
    double projection = 0.0;
    for (std::size_t a = first_[t]; a < first_[t + 1]; ++a)
      projection += gradients_[a].dot(x[static_cast<std::size_t>(nodes_[a])]);
    const double scale = coefficient_[t] * projection;
    for (std::size_t a = first_[t]; a < first_[t + 1]; ++a)
      y[static_cast<std::size_t>(nodes_[a])] += scale * gradients_[a];
  }
}

double largest_eigenvalue(const RankOneSystem& a, std::span<const double> inverse_mass,
                          int max_iterations, double tolerance) {
  const std::size_t n = a.node_count();
  if (inverse_mass.size() != n)
    throw core::UsageError("largest_eigenvalue needs one inverse mass per node");
  std::vector<double> scale(n);
  std::vector<core::Vec3> x(n), y(n), scaled(n);
  for (std::size_t i = 0; i < n; ++i) {
    scale[i] = inverse_mass[i] > 0.0 ? std::sqrt(inverse_mass[i]) : 0.0;
    for (int axis = 0; axis < 3; ++axis)
      x[i][axis] = scale[i] > 0.0 ? start_component(3 * i + static_cast<std::size_t>(axis)) : 0.0;
  }
  double length = norm(x);
  if (length == 0.0) return 0.0;  // every node fixed
  for (auto& v : x)
    v /= length;

  constexpr int kWindow = 20;
  std::vector<double> quotient;
  quotient.reserve(static_cast<std::size_t>(max_iterations));
  for (int k = 0; k < max_iterations; ++k) {
    // y = S A S x with S = M^-1/2: symmetric, with the eigenvalues of M⁻¹A.
    for (std::size_t i = 0; i < n; ++i)
      scaled[i] = scale[i] * x[i];
    a.multiply(scaled, y);
    double rayleigh = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] *= scale[i];
      rayleigh += x[i].dot(y[i]);
    }
    quotient.push_back(rayleigh);
    length = norm(y);
    if (length == 0.0) return 0.0;
    for (std::size_t i = 0; i < n; ++i)
      x[i] = y[i] / length;
    if (k >= kWindow) {
      const double earlier = quotient[static_cast<std::size_t>(k - kWindow)];
      if (rayleigh - earlier <= tolerance * rayleigh) break;
    }
  }
  return quotient.back();
}

double verlet_stable_step(double omega_squared, double damping_rate) {
  const double c = std::max(0.0, damping_rate);
  const double w2 = std::max(0.0, omega_squared);
  if (c == 0.0 && w2 == 0.0) return std::numeric_limits<double>::infinity();
  return 4.0 / (c + std::sqrt(c * c + 4.0 * w2));
}

}  // namespace viscera::sim
