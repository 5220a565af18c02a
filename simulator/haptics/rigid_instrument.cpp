#include "simulator/haptics/rigid_instrument.h"

#include "core/error.h"

namespace viscera::sim {

RigidInstrument::RigidInstrument(std::vector<core::Vec3> points, double stiffness)
    : local_(std::move(points)) {
  if (local_.empty()) throw core::UsageError("an instrument needs at least one interaction point");
  proxies_.assign(local_.size(), HapticProxy(stiffness));
}

RigidInstrument RigidInstrument::shaft(double length, int count, double stiffness) {
  if (count < 2 || !(length > 0.0))
    throw core::UsageError("a shaft needs a positive length and at least two points");
  std::vector<core::Vec3> points;
  for (int i = 0; i < count; ++i)
    points.emplace_back(0.0, 0.0, length * i / (count - 1));
  return RigidInstrument(std::move(points), stiffness);
}

void RigidInstrument::reset(const InstrumentPose& pose) {
  pose_ = pose;
  for (std::size_t i = 0; i < local_.size(); ++i)
    proxies_[i].reset(point(i));
}

void RigidInstrument::update(const InstrumentPose& pose, const ProxySurface& surface,
                             std::span<const core::Vec3> positions) {
  pose_ = pose;
  for (std::size_t i = 0; i < local_.size(); ++i)
    proxies_[i].update(point(i), surface, positions);
}

core::Vec3 RigidInstrument::force() const {
  core::Vec3 total = core::Vec3::Zero();
  for (const auto& proxy : proxies_)
    total += proxy.force();
  return total;
}

core::Vec3 RigidInstrument::torque_about(const core::Vec3& pivot) const {
  core::Vec3 total = core::Vec3::Zero();
  // The spring acts between proxy and tool point; on the rigid tool it acts at the point.
  for (std::size_t i = 0; i < proxies_.size(); ++i)
    total += (point(i) - pivot).cross(proxies_[i].force());
  return total;
}

std::vector<TissueLoad> RigidInstrument::tissue_loads() const {
  std::vector<TissueLoad> loads;
  for (const auto& proxy : proxies_) {
    if (proxy.in_contact())
      loads.push_back({proxy.contact().triangle, proxy.contact().barycentric, -proxy.force()});
  }
  return loads;
}

}  // namespace viscera::sim
