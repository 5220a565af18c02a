#pragma once
/// Organ motility as forces in the session (Kühnapfel et al., KISMET; seed 001 §5.2, eq. 6–7):
/// every free knot of the target body is pulled by a spring toward its rest position moved by
/// OrganMotility's displacement at the end of the step (physics/organ_motility.h: travelling
/// radial and longitudinal waves plus impulsive contractions),
///   f_i = −k_i (x_i − X_i − d_i(t + h)),   E = Σ ½ k_i |x_i − X_i − d_i(t + h)|²,
/// with k_i the node's own stiffness against its neighbours in the tissue at rest,
///   k_i = kStiffnessFactor · ⅓ Σ_{tet edges e at i} k_D,e / D0,e²   (N/m),
/// k_D,e = Σ over the edge's tets of distance_stiffness × V0/6 (the Teschner distance
/// stiffness, seed 000 §3, of each tet's material; node_distance_stiffness in body_model.h):
/// as stiff as the tissue around the knot, so a smooth motility field (wavelength ≫ the mesh) is
/// carried out nearly in full, while the instrument, connections and the tissue's elasticity
/// still deform the body. The Hessian is k_i I (positive semi-definite: the implicit integrator
/// stays stable); held nodes get none.

#include <optional>

#include "core/scenario/scenario_parts.h"
#include "simulator/dynamics/body_term.h"
#include "simulator/physics/organ_motility.h"

namespace viscera::sim {

class MotilityForces : public BodyTerm {
 public:
  /// Motility spring stiffness as a multiple of the node's local distance stiffness.
  static constexpr double kStiffnessFactor = 1.0;

  /// Motility `spec` on the body of `model` (with tets), its amplitudes and frequencies drawn
  /// with `seed`; `id` names the active deformation. Throws core::InputError naming it for an
  /// unusable spec or a body without tets.
  MotilityForces(std::shared_ptr<const BodyModel> model, const SimulationState& state,
                 const core::MotilitySpec& spec, std::uint64_t seed, std::string id);

  std::string name() const override { return "motility " + id_ + " " + model().name; }
  /// Moves the spring anchors to the rest positions displaced at time + h.
  void prepare(const SimulationState& state, const StepContext& context) override;
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override {}  // diagonal blocks only
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  /// The organ moves by itself: its body never falls asleep.
  bool drives() const override { return true; }

  const OrganMotility& motility() const { return *motility_; }
  /// Where the springs pull the body's nodes (body-local order), m.
  const std::vector<Vec3>& anchors() const { return anchors_; }
  /// k_i in N/m per body node.
  const std::vector<double>& stiffness() const { return stiffness_; }

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override { first_ += delta; }

 private:
  core::MotilitySpec spec_;
  std::uint64_t seed_;
  std::string id_;
  int first_ = 0;
  std::optional<OrganMotility> motility_;
  std::vector<double> stiffness_;  ///< N/m per body node, 0 for held nodes
  std::vector<Vec3> anchors_;
};

}  // namespace viscera::sim
