#pragma once
/// The device thread's local force model between physics steps (seed 000 §8.2: "virtual
/// coupling techniques provide a data exchange between the fast haptic control loop and the
/// slower virtual environment"; surface meshes "are used for … local proxy updates"). After
/// every physics step the physics thread publishes the surface of the body under the
/// instrument; the device thread moves its own point proxy (Ruspini et al. 1997, HapticProxy)
/// of the session's stiffness over that latest surface for every device pose, at ≥ 1 kHz,
/// and renders its spring force. The physics thread's proxy is what loads the tissue; this one
/// only keeps the hand's force fresh between steps. Without a World body under the instrument
/// (a urethra lattice) the model holds the last physics step's force.

#include <span>
#include <vector>

#include "core/math_types.h"
#include "simulator/haptics/haptic_proxy.h"

namespace viscera::sim {

/// The tissue under the instrument after one physics step, as the device thread sees it.
struct TissueSnapshot {
  long long steps = 0;
  core::Vec3 force = core::Vec3::Zero();  ///< N, the physics step's force on the instrument
  bool in_contact = false;                ///< the physics step's proxy touches the surface
  std::vector<core::Vec3> surface;        ///< the body's surface nodes (ContactSurface order), m
};

/// The surface of one body as compact triangles over its surface nodes, so a snapshot copies
/// only those nodes. Immutable once built: shared by the physics and device threads.
class ContactSurface {
 public:
  ContactSurface() = default;
  /// `faces` index the body's nodes.
  explicit ContactSurface(const std::vector<core::Triangle>& faces);

  bool empty() const { return nodes_.empty(); }
  /// The body node of every surface node, in snapshot order.
  const std::vector<int>& nodes() const { return nodes_; }
  /// The faces over surface node indices.
  const std::vector<core::Triangle>& faces() const { return faces_; }
  /// Copies the surface nodes of `body_positions` into `out` (resized).
  void gather(std::span<const core::Vec3> body_positions, std::vector<core::Vec3>& out) const;

 private:
  std::vector<int> nodes_;
  std::vector<core::Triangle> faces_;
};

/// The point proxy of the device thread.
class LocalContactModel {
 public:
  /// `surface` of the body under the instrument (empty: hold the physics force); `stiffness`
  /// of the proxy–tip spring in N/m, as the session's instrument.
  LocalContactModel(const ContactSurface& surface, double stiffness);

  /// Takes the latest tissue state (the physics thread's newest snapshot).
  void set_tissue(const TissueSnapshot& tissue) { tissue_ = &tissue; }
  /// Moves the proxy for the device's tip at `tip` (m) and returns the force on the hand, N:
  /// the proxy spring over the latest surface; the physics force without a surface or before
  /// the first snapshot. The first call places the proxy at the tip.
  core::Vec3 force_at(const core::Vec3& tip);
  bool in_contact() const { return proxy_.in_contact(); }
  const HapticProxy& proxy() const { return proxy_; }

 private:
  ProxySurface surface_;
  bool has_surface_ = false;
  HapticProxy proxy_;
  const TissueSnapshot* tissue_ = nullptr;
  bool placed_ = false;
};

}  // namespace viscera::sim
