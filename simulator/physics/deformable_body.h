#pragma once
/// A tetrahedral body simulated with the Teschner energies (seed 000 §3). The body gathers its
/// arrays and rest data once per topology; the energies and the integrator are plain functions.

#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/scenario/material.h"
#include "simulator/physics/kismo_mass_spring.h"
#include "simulator/physics/stable_step.h"
#include "simulator/physics/teschner_energies.h"

namespace viscera::sim {

/// Energies of a body in J.
struct BodyEnergies {
  double kinetic = 0.0;
  double elastic = 0.0;        ///< distance + area + volume terms
  double gravitational = 0.0;  ///< relative to the rest configuration
  double total() const { return kinetic + elastic + gravitational; }
};

/// How a body's internal forces and integration work.
enum class BodyModel {
  Teschner,        ///< distance, area and volume energies with Verlet (seed 000 §3)
  KismoMassSpring  ///< cubic springs on the mesh edges with per-knot damping (seed 001 §3.2)
};

/// Rest data, state and parameters of one deformable tet body.
///
/// Stiffness convention: Material stores densities, turned into per-term constants here so a
/// material behaves alike at any mesh resolution — k_D of an edge = distance_stiffness (Pa) ×
/// the edge's volume share (Σ V_tet/6 over its tets), k_d likewise from distance_damping,
/// k_A of a surface triangle = area_stiffness (N/m) × A0, k_V of a tet = volume_stiffness (Pa)
/// × V0.
class DeformableBody {
 public:
  /// Builds rest data from `mesh` (masses from mesh.node_mass, or lumped from the density;
  /// fixed nodes from mesh.fixed). Throws core::InputError naming `name` for a mesh with
  /// degenerate tets or non-positive masses.
  /// KisMo nets use the same mesh edges as springs: with a stress-strain cubic σ = c1 ε + c2 ε²
  /// + c3 ε³ in the material, each spring gets k_n = c_n × its cross-section (volume share / rest
  /// length); without one, k1 = distance_stiffness × the same cross-section, which matches the
  /// Teschner distance term for small strains. Each spring has a damping element of
  /// distance_damping × share / l0², like the Teschner distance damping.
  DeformableBody(std::string name, const core::TetMesh& mesh, const core::Material& material,
                 BodyModel model = BodyModel::Teschner);

  BodyModel model() const { return model_; }
  const CubicSprings& springs() const { return springs_; }

  const std::string& name() const { return name_; }
  std::size_t node_count() const { return positions_.size(); }
  const DistanceTerms& distance_terms() const { return distance_; }
  const AreaTerms& area_terms() const { return area_; }
  const VolumeTerms& volume_terms() const { return volume_; }

  std::vector<core::Vec3>& positions() { return positions_; }
  const std::vector<core::Vec3>& positions() const { return positions_; }
  std::vector<core::Vec3>& previous_positions() { return previous_; }
  const std::vector<core::Vec3>& previous_positions() const { return previous_; }
  const std::vector<core::Vec3>& rest_positions() const { return rest_; }
  const std::vector<double>& masses() const { return mass_; }
  const std::vector<double>& inverse_masses() const { return inverse_mass_; }

  /// Computes the forces of all terms plus gravity (m/s²) for step length h (s) and returns
  /// the elastic energy at the current positions. Fills forces().
  double compute_forces(const core::Vec3& gravity, double h);
  const std::vector<core::Vec3>& forces() const { return forces_; }

  /// Adds an external force in N at `node` (contacts, instruments) after compute_forces().
  void add_force(int node, const core::Vec3& force) { forces_[node] += force; }
  /// Boundary triangles of the body, outward (TetMesh::surface_faces or derived from tets).
  const std::vector<core::Triangle>& surface_faces() const { return surface_faces_; }

  /// One Verlet step of h seconds with the forces of compute_forces().
  void integrate(double h);

  /// Energies at the current state, velocities from the last step of length h.
  BodyEnergies energies(const core::Vec3& gravity, double h) const;

  /// Largest step in s for which explicit integration of this body stays stable, from a
  /// Gershgorin bound on the stiffness and damping of each node, with a 0.9 safety factor.
  /// `contact_stiffness` (N/m) is the penalty stiffness surface nodes may meet in contacts;
  /// `node_stiffness` (N/m, empty or one per node) what springs to other bodies add to a node's
  /// row (2k for a spring of stiffness k to another body's node).
  double stable_time_step(double contact_stiffness = 0.0,
                          std::span<const double> node_stiffness = {}) const;

  /// Adds the Hessian of the body's Teschner terms at rest, Σ k ∇C ∇Cᵀ, to `stiffness` and the
  /// distance damping Σ k_d ∇C ∇Cᵀ to `damping`, with this body's nodes numbered from `offset`
  /// (see RankOneSystem). A KisMo net adds nothing: its own integrator keeps the bound of
  /// stable_time_step(). Returns whether terms were added.
  bool add_linearised_terms(RankOneSystem& stiffness, RankOneSystem& damping, int offset) const;

  /// Largest distance in m of any node from its rest position.
  double max_displacement() const;
  /// Centre of mass in m.
  core::Vec3 centre_of_mass() const;
  /// Centre of mass of the rest configuration in m.
  core::Vec3 rest_centre_of_mass() const;

 private:
  void build_springs(const core::Material& material, const std::map<std::array<int, 2>, double>& volume_share);

  std::string name_;
  BodyModel model_;
  std::vector<core::Vec3> rest_, positions_, previous_, velocities_, forces_;
  CubicSprings springs_;
  KnotParameters knots_;
  std::vector<double> mass_, inverse_mass_;
  std::vector<core::Triangle> surface_faces_;
  DistanceTerms distance_;
  AreaTerms area_;
  VolumeTerms volume_;
};

}  // namespace viscera::sim
