#include "tests/meshing/label_phantoms.h"

#include <cmath>
#include <functional>
#include <numbers>

namespace viscera::testing {
namespace {

/// Fills a map whose box covers `half_extent` (m, in the phantom's frame) around the centre;
/// `inside(q)` gives the label at phantom-frame point q.
core::LabelMap sample(const PhantomFrame& frame, double half_extent, int margin,
                      const std::function<int(const core::Vec3&)>& inside) {
  core::LabelMap map;
  auto& image = map.image;
  image.scalar_type = core::ScalarType::UInt16;
  image.spacing = frame.spacing;
  image.direction = frame.direction;
  for (int a = 0; a < 3; ++a)
    image.dims[a] = static_cast<int>(std::ceil(2.0 * half_extent / frame.spacing[a])) + 2 * margin;
  // Place the centre at the middle of the box: origin = centre − D·(spacing ∘ (dims−1)/2).
  const core::Vec3 half_box(0.5 * (image.dims[0] - 1), 0.5 * (image.dims[1] - 1),
                            0.5 * (image.dims[2] - 1));
  image.origin = frame.centre - frame.direction * frame.spacing.cwiseProduct(half_box);
  image.allocate();
  for (int k = 0; k < image.dims[2]; ++k)
    for (int j = 0; j < image.dims[1]; ++j)
      for (int i = 0; i < image.dims[0]; ++i) {
        const core::Vec3 world = image.index_to_world(core::Vec3(i, j, k));
        const core::Vec3 q = frame.direction.transpose() * (world - frame.centre);
        map.set_label(image.linear_index(i, j, k), static_cast<std::uint16_t>(inside(q)));
      }
  return map;
}

}  // namespace

PhantomFrame PhantomFrame::rotated(double degrees, bool mirror) {
  PhantomFrame frame;
  frame.direction =
      Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, core::Vec3(1, 2, 3).normalized())
          .toRotationMatrix();
  if (mirror) frame.direction.col(0) = -frame.direction.col(0);
  frame.centre = core::Vec3(0.08, 0.01, 0.14);
  return frame;
}

core::LabelMap spheroid_phantom(double a, double c, const PhantomFrame& frame, int label,
                                int margin) {
  return sample(frame, c, margin, [&](const core::Vec3& q) {
    const double s = (q.x() * q.x() + q.y() * q.y()) / (a * a) + q.z() * q.z() / (c * c);
    return s <= 1.0 ? label : 0;
  });
}

core::LabelMap torus_phantom(double R, double r, const PhantomFrame& frame, int margin) {
  return sample(frame, R + r, margin, [&](const core::Vec3& q) {
    const double ring = std::hypot(q.x(), q.y()) - R;
    return ring * ring + q.z() * q.z() <= r * r ? 1 : 0;
  });
}

core::LabelMap shell_phantom(double a, double c, double inner, const PhantomFrame& frame) {
  return sample(frame, c, 3, [&](const core::Vec3& q) {
    if (q.norm() <= inner) return 2;
    const double s = (q.x() * q.x() + q.y() * q.y()) / (a * a) + q.z() * q.z() / (c * c);
    return s <= 1.0 ? 1 : 0;
  });
}

double spheroid_volume(double a, double c) {
  return 4.0 / 3.0 * std::numbers::pi * a * a * c;
}

double spheroid_area(double a, double c) {
  if (c == a) return 4.0 * std::numbers::pi * a * a;
  const double e = std::sqrt(1.0 - a * a / (c * c));
  return 2.0 * std::numbers::pi * a * a * (1.0 + c * std::asin(e) / (a * e));
}

double torus_volume(double R, double r) {
  return 2.0 * std::numbers::pi * std::numbers::pi * R * r * r;
}

double torus_area(double R, double r) {
  return 4.0 * std::numbers::pi * std::numbers::pi * R * r;
}

}  // namespace viscera::testing
