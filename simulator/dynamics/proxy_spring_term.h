#pragma once
/// The instrument's proxy spring (Ruspini et al. 1997; seed 000 §8.2) as a force term. The proxy
/// walks over ONE surface made of every body's boundary triangles in global node numbers, so
/// the tool meets whatever body it reaches (a polyp in front of the wall included). prepare()
/// moves the proxy for the tip; in contact the proxy point is the barycentric point
/// p(x) = Σ b_k x_k of its triangle, and E = ½ k |p(x) − tip|² pulls the surface towards the tip:
/// the tissue feels −k b_k (p − tip), the hand k (p − tip). Hessian k b bᵀ ⊗ I.

#include <memory>
#include <vector>

#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/force_term.h"
#include "simulator/haptics/haptic_proxy.h"

namespace viscera::sim {

class ProxySpringTerm : public ForceTerm {
 public:
  ProxySpringTerm(std::vector<std::shared_ptr<const BodyModel>> models, double stiffness,
                  const SimulationState& state, const Vec3& tip);
  std::string name() const override { return "instrument-proxy"; }
  void prepare(const SimulationState& state, const StepContext& context) override;
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  bool structure_changed() const override { return structure_changed_; }
  /// After the step: the proxy rides on its triangle at the new positions.
  void after_step(const SimulationState& state) override;
  void topology_changed(const SimulationState& state, int body) override;
  double worst_case_node_stiffness() const override { return proxy_.stiffness(); }
  std::span<const int> worst_case_nodes() const override { return surface_nodes_; }
  /// The proxy acts only near the tip: within a step the tip stands still and the proxy only
  /// gets nearer to it (it walks towards the point nearest the tip, or is released and tests
  /// the path to it), so the reach is the box around the tip of half-width |tip − proxy| +
  /// kReachMargin, the margin for the surfaces' own motion.
  bool worst_case_within_reach() const override { return true; }
  core::BoundingBox reach() const override;
  static constexpr double kReachMargin = 5e-3;  ///< m: 5 m/s of tissue motion over a 1 ms step

  void set_tip(const Vec3& tip) { tip_ = tip; }
  const Vec3& tip() const { return tip_; }
  const HapticProxy& proxy() const { return proxy_; }
  const ProxySurface& surface() const { return *surface_; }
  /// Body of the touched triangle, or −1 when free.
  int touched_body() const;
  /// The touched triangle's index within its body's surface, or −1.
  int touched_body_triangle() const;

 private:
  /// Every body's surface, or only `changed_body`'s when it is ≥ 0, then the joined surface.
  void rebuild(const SimulationState& state, int changed_body);
  std::vector<std::shared_ptr<const BodyModel>> models_;
  std::vector<ProxySurface> body_surfaces_;  ///< per body, in its own node numbers
  std::unique_ptr<ProxySurface> surface_;
  /// surface_'s box tree: built at the first prepare() after a rebuild, marked moved after
  /// every integrated (sub-)step and refitted by the first query after that; a sleeping
  /// world's steps reuse it.
  ProxySurfaceTree tree_;
  bool tree_built_ = false;
  long long recaptured_at_step_ = -1;        ///< the step whose first prepare() ran recapture()
  std::vector<int> face_body_, face_first_;  ///< per global face: body; per body: first face
  std::vector<int> surface_nodes_;
  HapticProxy proxy_;
  Vec3 tip_;
  std::array<int, 3> active_{-1, -1, -1};
  std::array<double, 3> weight_{};
  bool structure_changed_ = false;
};

}  // namespace viscera::sim
