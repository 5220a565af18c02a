#pragma once
/// Smooth random deformation fields for organ shape variability (issue 6): a displacement
/// d(x) = Σ_k w_k exp(−|x − c_k|² / 2σ²) with random centres c_k in a box and random vector
/// weights w_k, scaled so that its Lipschitz constant stays below a bound L < 1. Then
/// x ↦ x + d(x) is injective (|d(x) − d(y)| ≤ L|x − y| < |x − y|), so a surface that did not
/// intersect itself still does not, and nested surfaces stay nested — every random organ is
/// as valid as the template's mean shape.

#include <vector>

#include "core/math_types.h"
#include "core/random.h"

namespace viscera::templates {

/// A sum of Gaussian radial basis displacements.
class SmoothDeformation {
 public:
  /// The identity.
  SmoothDeformation() = default;

  /// `centres` random centres drawn uniformly in `box`, each with a weight whose components are
  /// normal(0, amplitude) m, the Gaussians of width `width` m; then all weights are scaled
  /// down, if needed, so the Lipschitz bound is at most `max_lipschitz` (< 1).
  /// Throws core::UsageError for a non-positive width, negative amplitude or bound ∉ [0, 1).
  static SmoothDeformation random(core::Rng& rng, const core::BoundingBox& box, int centres,
                                  double amplitude, double width, double max_lipschitz = 0.5);

  /// d(x) in m.
  core::Vec3 displacement(const core::Vec3& x) const;
  /// x + d(x).
  core::Vec3 apply(const core::Vec3& x) const { return x + displacement(x); }
  /// Applies the map to every point.
  void apply(std::vector<core::Vec3>& points) const;
  /// A unit normal carried through the map (the image of a short step along it).
  core::Vec3 apply_direction(const core::Vec3& x, const core::Vec3& direction) const;

  /// An upper bound of the Lipschitz constant: Σ|w_k| · e^(−1/2) / σ.
  double lipschitz_bound() const;

 private:
  std::vector<core::Vec3> centres_;
  std::vector<core::Vec3> weights_;
  double width_ = 1.0;
};

}  // namespace viscera::templates
