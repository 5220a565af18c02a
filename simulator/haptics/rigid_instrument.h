#pragma once
/// Rigid instruments as point sets along shaft and tip (seed 000 §8.2: "surgical tools are
/// approximated by a collection of points"). Each point has its own proxy on the tissue
/// surface; the instrument feels the sum of their spring forces and the torque of those forces
/// about its pivot, and the tissue receives the opposite forces at the proxies.

#include <Eigen/Geometry>
#include <vector>

#include "simulator/haptics/haptic_proxy.h"

namespace viscera::sim {

/// Where the instrument is: the origin of its frame (the handle end of the shaft) and its
/// orientation; the shaft points along the frame's +z axis.
struct InstrumentPose {
  core::Vec3 position = core::Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// One force the instrument puts on the tissue, at a proxy on a surface triangle.
struct TissueLoad {
  int triangle = -1;
  std::array<double, 3> barycentric{};
  core::Vec3 force = core::Vec3::Zero();  ///< N, on the tissue
};

/// A rigid tool made of interaction points, each rendered with a point proxy.
class RigidInstrument {
 public:
  /// `points` in the tool frame (m); `stiffness` of each proxy spring in N/m.
  RigidInstrument(std::vector<core::Vec3> points, double stiffness);

  /// A straight shaft of `length` m with `count` ≥ 2 points from the frame origin to the tip.
  static RigidInstrument shaft(double length, int count, double stiffness);

  /// Moves every point's proxy for the new pose against `surface` at `positions`.
  void update(const InstrumentPose& pose, const ProxySurface& surface,
              std::span<const core::Vec3> positions);
  /// Places every proxy at its point for `pose` with no contact.
  void reset(const InstrumentPose& pose);

  /// Total force in N on the instrument.
  core::Vec3 force() const;
  /// Torque in N·m on the instrument about `pivot` (e.g. the trocar or the device's centre of
  /// rotation): Σ (proxy − pivot) × F.
  core::Vec3 torque_about(const core::Vec3& pivot) const;
  /// The shaft direction in world coordinates.
  core::Vec3 axis() const { return pose_.orientation * core::Vec3::UnitZ(); }
  /// The forces on the tissue, one per point in contact.
  std::vector<TissueLoad> tissue_loads() const;

  /// World position of point i for the current pose.
  core::Vec3 point(std::size_t i) const { return pose_.position + pose_.orientation * local_[i]; }
  const std::vector<HapticProxy>& proxies() const { return proxies_; }

 private:
  std::vector<core::Vec3> local_;
  std::vector<HapticProxy> proxies_;
  InstrumentPose pose_;
};

}  // namespace viscera::sim
