#pragma once
/// The agent-based tissue of seed 003 §V (Kuzub) as a body of the session: its cells are the
/// body's nodes, integrated with every other body by the world's integrator, pressed by the
/// instrument through the proxy over the tissue's surface triangles. Per cell i with home X_i
/// (its rest position) and per connection c = (a, b) found at start-up
/// (physics/cell_agent_tissue.h: discover_cell_connections):
///   E = Σ_c ½ k_c (|x_b − x_a| − l0_c)²  +  Σ_i ½ k_home,i |x_i − X_i|²      (eq. 3–4)
///   f_i = −∂E/∂x_i − (m_i b_i / h) v_i                                       (eq. 6's damping b,
///                                                   "fraction of velocity removed per step" h)
/// plus the elastic collision of eq. 8–9 between connected cells closer than their radii,
/// ½ k_collision m (v_rel · n)² along the line of centres pushing them apart (not an energy,
/// left out of the damping matrix). Hessian: each connection's radial block (projection clamps
/// the across-term k (1 − l0/l) at zero when compressed), k_home,i I on the diagonal; damping
/// matrix (m_i b_i / h) I.
///
/// After every accepted step the connections tear and yield (tear_and_yield: past the cell
/// types' tear strain from the original length they break and are recorded as TearEvents; past
/// the yield strain their rest length grows). cut() removes the connections a blade crosses.
///
/// The seed's model is 2D. A session's tool presses the sheet from outside its plane, so the
/// cells move in 3D: out of the plane the home springs (the seed's "connection to an underlying
/// plane") and the stretched connections hold them. CellTissueSpec::planar keeps the stand-alone
/// CellAgentTissue in its plane; it does not constrain this body.

#include "core/scenario/scenario_parts.h"
#include "simulator/dynamics/body_term.h"
#include "simulator/dynamics/tissue_tearing.h"
#include "simulator/physics/cell_agent_tissue.h"

namespace viscera::sim {

class AgentTissueTerm : public BodyTerm {
 public:
  /// The cells of `model` (kind CellAgent: mesh.nodes are the homes) with the types of `spec`;
  /// `time_step` s turns the per-step damping b into a viscous coefficient. Throws
  /// core::InputError naming the object and the place (`where`: the spec's JSON pointer in the
  /// scenario, e.g. "/scenario/cell_tissues/0") when spec.cell_types does not give every cell
  /// a type among spec.types.
  AgentTissueTerm(std::shared_ptr<const BodyModel> model, const SimulationState& state,
                  core::CellTissueSpec spec, double time_step, const std::string& where = "");

  std::string name() const override { return "cell-agents " + model().name; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  void add_damping(std::span<const Vec3> x, double scale, BlockSparseMatrix&) const override;
  /// Tearing and plastic flow of the connections at the accepted positions.
  void after_step(const SimulationState& state) override;

  /// Removes every connection whose segment, at the state's positions, crosses triangle
  /// (a, b, c) — a blade swept through the tissue (seed 003 §V cutting); returns how many.
  int cut(const SimulationState& state, const Vec3& a, const Vec3& b, const Vec3& c);

  /// Connections with body-local cell indices.
  const std::vector<CellConnection>& connections() const { return connections_; }
  const std::vector<TearEvent>& tears() const { return tears_; }
  /// Viscous coefficient m_i b_i / h of cell i, N·s/m.
  double damping(int cell) const { return damping_[static_cast<std::size_t>(cell)]; }

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override { first_ += delta; }

 private:
  core::CellTissueSpec spec_;
  double time_step_;
  int first_ = 0;
  std::vector<CellType> types_;
  std::vector<CellConnection> connections_;
  std::vector<Vec3> homes_;  ///< m, the cells' rest positions
  std::vector<double> home_stiffness_, damping_, radius_, efficiency_, mass_;
  std::vector<TearEvent> tears_;
};

}  // namespace viscera::sim
