#pragma once
/// Point-proxy ("god-object") haptic rendering (Ruspini, Kolarov & Khatib 1997; seed 000 §8.2).
/// The proxy follows the instrument tip in free space; once the tip enters an object the proxy
/// stays on the object's surface at the point that locally minimises its distance to the tip.
/// A linear spring between proxy and tip gives the force on the hand, and the opposite force
/// is spread over the nodes of the surface triangle under the proxy.

#include <array>
#include <span>
#include <vector>

#include "core/math_types.h"
#include "simulator/haptics/proxy_surface_tree.h"

namespace viscera::sim {

/// A triangle surface at its current positions, with triangle adjacency for walking over it.
class ProxySurface {
 public:
  /// `faces` outward; keeps a copy of the connectivity, reads positions on every update.
  explicit ProxySurface(std::vector<core::Triangle> faces);
  /// The surfaces `parts` side by side: part k's vertices shifted by vertex_offsets[k], its
  /// triangles by the faces before it (no edge joins two parts). Their adjacency is copied,
  /// not searched again.
  static ProxySurface joined(std::span<const ProxySurface> parts,
                             std::span<const int> vertex_offsets);

  const std::vector<core::Triangle>& faces() const { return faces_; }
  /// The triangle across edge e (vertices e, e+1) of triangle t, or −1 on a border.
  int neighbour(int t, int e) const { return neighbours_[static_cast<std::size_t>(t)][e]; }

 private:
  ProxySurface() = default;
  std::vector<core::Triangle> faces_;
  std::vector<std::array<int, 3>> neighbours_;
};

/// The proxy's contact with a surface: which triangle and where on it.
struct ProxyContact {
  int triangle = -1;                    ///< −1 when the proxy is free
  std::array<double, 3> barycentric{};  ///< of the proxy in that triangle
};

/// State and update of one proxy point.
class HapticProxy {
 public:
  /// `stiffness` of the proxy–tip spring in N/m.
  explicit HapticProxy(double stiffness);

  /// Moves the proxy for a new tip position (m) against `surface` at `positions`. Free: the
  /// proxy goes to the tip unless the segment from the old proxy to the tip enters the surface
  /// from outside, which starts a contact at the crossing. In contact: the proxy walks over the
  /// surface to the point nearest the tip, or is released when the tip is back outside.
  /// `tree`, when given, is `surface`'s box tree (refitted to `positions` if marked moved): the
  /// same answer, found without testing every triangle.
  void update(const core::Vec3& tip, const ProxySurface& surface,
              std::span<const core::Vec3> positions, ProxySurfaceTree* tree = nullptr);

  const core::Vec3& proxy() const { return proxy_; }
  /// Proxy–tip spring stiffness in N/m.
  double stiffness() const { return stiffness_; }
  const ProxyContact& contact() const { return contact_; }
  bool in_contact() const { return contact_.triangle >= 0; }
  /// Force in N on the instrument: stiffness · (proxy − tip); zero when free.
  core::Vec3 force() const;
  /// Places the proxy at `position` with no contact (a tool entering the scene).
  void reset(const core::Vec3& position);
  /// For a free proxy whose tip lies inside the closed `surface` (a moving wall swept over the
  /// tip, which the path test of update() cannot see): starts the contact at the surface point
  /// nearest the tip and returns true. Inside is decided by the parity of the crossings of a
  /// ray from the tip. Does nothing (false) in contact or with the tip outside. `tree` as for
  /// update().
  bool recapture(const ProxySurface& surface, std::span<const core::Vec3> positions,
                 ProxySurfaceTree* tree = nullptr);

 private:
  double stiffness_;
  core::Vec3 proxy_ = core::Vec3::Zero();
  core::Vec3 tip_ = core::Vec3::Zero();
  ProxyContact contact_;
};

/// Spreads a force applied at a surface point to the three nodes of its triangle by the
/// point's barycentric weights; returns (node, force) triples in node order of the triangle.
std::array<std::pair<int, core::Vec3>, 3> distribute_to_triangle(
    const core::Triangle& triangle, const std::array<double, 3>& barycentric,
    const core::Vec3& force);

/// The closest point to `p` on triangle (a, b, c) and its barycentric coordinates
/// (Ericson 2005, Real-Time Collision Detection §5.1.5).
core::Vec3 closest_point_on_triangle(const core::Vec3& p, const core::Vec3& a, const core::Vec3& b,
                                     const core::Vec3& c, std::array<double, 3>& barycentric);

}  // namespace viscera::sim
