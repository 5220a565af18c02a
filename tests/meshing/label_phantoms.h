#pragma once
/// Generated label maps with analytic surface area and volume (issue 3 §8): ellipsoids (as
/// prolate spheroids, whose area has a closed form), tori, and a two-label shell. Each phantom
/// sits in a map with anisotropic spacing, a rotated direction matrix and a non-zero origin, so
/// the geometry handling is part of every check.

#include "core/image/image_volume.h"

namespace viscera::testing {

/// Where a phantom lies in the world and how its voxels are laid out.
struct PhantomFrame {
  core::Vec3 spacing{0.001, 0.0009, 0.0011};  ///< m
  core::Vec3 origin{0.05, -0.02, 0.11};       ///< m
  core::Mat3 direction;                       ///< rotation (or mirror when requested)
  core::Vec3 centre;                          ///< world position of the phantom's centre, m

  /// A frame rotated by `degrees` about (1, 2, 3); `mirror` negates the first column.
  static PhantomFrame rotated(double degrees, bool mirror = false);
};

/// Label `label` inside the prolate spheroid with semi-axes (a, a, c) (m, c ≥ a, axis along the
/// frame's third direction), 0 outside; the map is sized to the phantom plus `margin` voxels.
core::LabelMap spheroid_phantom(double a, double c, const PhantomFrame& frame, int label = 1,
                                int margin = 3);
/// Label 1 inside the torus of centre radius R and tube radius r (m) around the third axis.
core::LabelMap torus_phantom(double R, double r, const PhantomFrame& frame, int margin = 3);
/// Label 1 in the spheroid (a, a, c) and label 2 in the concentric sphere of radius `inner`.
core::LabelMap shell_phantom(double a, double c, double inner, const PhantomFrame& frame);

double spheroid_volume(double a, double c);
double spheroid_area(double a, double c);  ///< prolate: 2πa²(1 + c·asin(e)/(a·e))
double torus_volume(double R, double r);   ///< 2π²Rr²
double torus_area(double R, double r);     ///< 4π²Rr

}  // namespace viscera::testing
