#include "templates/variability/smooth_deformation.h"

#include <cmath>

#include "core/error.h"

namespace viscera::templates {

SmoothDeformation SmoothDeformation::random(core::Rng& rng, const core::BoundingBox& box,
                                            int centres, double amplitude, double width,
                                            double max_lipschitz) {
  if (!(width > 0.0)) throw core::UsageError("deformation width must be positive");
  if (!(amplitude >= 0.0)) throw core::UsageError("deformation amplitude must not be negative");
  if (!(max_lipschitz >= 0.0 && max_lipschitz < 1.0)) {
    throw core::UsageError("deformation Lipschitz bound must lie in [0, 1)");
  }
  SmoothDeformation field;
  field.width_ = width;
  for (int k = 0; k < centres; ++k) {
    core::Vec3 c;
    for (int a = 0; a < 3; ++a)
      c[a] = rng.uniform(box.min[a], box.max[a]);
    core::Vec3 w;
    for (int a = 0; a < 3; ++a)
      w[a] = rng.normal(0.0, amplitude);
    field.centres_.push_back(c);
    field.weights_.push_back(w);
  }
  const double bound = field.lipschitz_bound();
  if (bound > max_lipschitz) {
    for (auto& w : field.weights_)
      w *= max_lipschitz / bound;
  }
  return field;
}

core::Vec3 SmoothDeformation::displacement(const core::Vec3& x) const {
  core::Vec3 d = core::Vec3::Zero();
  const double inv = 1.0 / (2.0 * width_ * width_);
  for (std::size_t k = 0; k < centres_.size(); ++k) {
    d += weights_[k] * std::exp(-(x - centres_[k]).squaredNorm() * inv);
  }
  return d;
}

void SmoothDeformation::apply(std::vector<core::Vec3>& points) const {
  for (auto& p : points)
    p = apply(p);
}

core::Vec3 SmoothDeformation::apply_direction(const core::Vec3& x,
                                              const core::Vec3& direction) const {
  const double step = 1e-4 * width_;
  const core::Vec3 image = apply(x + step * direction) - apply(x);
  const double length = image.norm();
  return length > 0.0 ? core::Vec3(image / length) : direction;
}

double SmoothDeformation::lipschitz_bound() const {
  // The gradient of exp(−r²/2σ²) has its largest magnitude e^(−1/2)/σ at r = σ.
  double sum = 0.0;
  for (const auto& w : weights_)
    sum += w.norm();
  return sum * std::exp(-0.5) / width_;
}

}  // namespace viscera::templates
