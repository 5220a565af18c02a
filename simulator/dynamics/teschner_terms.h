#pragma once
/// The Teschner et al. 2004 energies (seed 000 §3, eq. 3–7) of one tet body as force terms,
/// each element with the stiffness of its own tet's material (wall layers). The maths of
/// energies and forces is physics/teschner_energies.h; these classes add rest data per
/// topology, Hessians and damping matrices.
///
/// Stiffness convention (as DeformableBody had it): k_D of an edge = Σ over its tets of
/// distance_stiffness (Pa) × V0/6, k_d likewise from distance_damping, k_A of a surface
/// triangle = area_stiffness (N/m) of the tet that owns it × A0, k_V of a tet = volume_stiffness
/// (Pa) × V0.
///
/// Hessians, E = ½ k C²: ∇²E = k ∇C ∇Cᵀ + k C ∇²C. Projected (implicit solves): distance terms
/// clamp the eigenvalues of their 3×3 edge block (k/D0² along the edge, k C/(D0 |d|) across it)
/// at zero, which is the exact projection of the element's Hessian; area and volume terms keep
/// the Gauss–Newton part k ∇C ∇Cᵀ (positive semi-definite by construction, exact at rest).

#include "simulator/dynamics/body_term.h"
#include "simulator/physics/teschner_energies.h"

namespace viscera::sim {

/// Distance terms on the tet edges (eq. 4) with their damping (eq. 7).
class TeschnerDistanceTerm : public BodyTerm {
 public:
  TeschnerDistanceTerm(std::shared_ptr<const BodyModel> model, const SimulationState& state);
  std::string name() const override { return "teschner-distance " + model().name; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  void add_damping(std::span<const Vec3> x, double scale, BlockSparseMatrix&) const override;
  const DistanceTerms& terms() const { return terms_; }
  /// Rest lengths may be moved by plasticity (after_step of another term); m.
  DistanceTerms& mutable_terms() { return terms_; }

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override;

 private:
  /// Slots (i,i), (j,j), (i,j), (j,i) of every edge in matrices of pattern `slots_for_`.
  const std::vector<std::array<int, 4>>& slots(const BlockSparseMatrix& m) const;
  DistanceTerms terms_;
  mutable std::vector<std::array<int, 4>> slots_;
  mutable std::uint64_t slots_for_ = 0;
};

/// Area terms on the surface triangles (eq. 5); none when every material's area stiffness is 0.
class TeschnerAreaTerm : public BodyTerm {
 public:
  TeschnerAreaTerm(std::shared_ptr<const BodyModel> model, const SimulationState& state);
  std::string name() const override { return "teschner-area " + model().name; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  const AreaTerms& terms() const { return terms_; }

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override;

 private:
  AreaTerms terms_;
};

/// Signed-volume terms on the tets (eq. 6).
class TeschnerVolumeTerm : public BodyTerm {
 public:
  TeschnerVolumeTerm(std::shared_ptr<const BodyModel> model, const SimulationState& state);
  std::string name() const override { return "teschner-volume " + model().name; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  const VolumeTerms& terms() const { return terms_; }
  /// First tet turned inside out at x — signed volume below −`fraction` × V0, a mirror image
  /// of itself — as a body-local tet index, or −1. A tet pressed flat and past zero under a
  /// point load (the tool's proxy pulls one triangle) is pushed back by its signed-volume term
  /// and is not an error; an everted one is beyond what the energy recovers.
  int first_inverted(std::span<const Vec3> x, double fraction = 1.0) const;

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override;

 private:
  /// Slots (a, b) of every tet, a·4 + b, in matrices of pattern `slots_for_`.
  const std::vector<std::array<int, 16>>& slots(const BlockSparseMatrix& m) const;
  VolumeTerms terms_;
  mutable std::vector<std::array<int, 16>> slots_;
  mutable std::uint64_t slots_for_ = 0;
};

}  // namespace viscera::sim
