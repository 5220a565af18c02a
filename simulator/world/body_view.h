#pragma once
/// A body of the world seen through the one SimulationState: its node range and its rest model.
/// Cheap to copy; valid until the world's next topology change of any body.

#include <span>
#include <string>

#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/simulation_state.h"

namespace viscera::sim {

class BodyView {
 public:
  BodyView(SimulationState* state, const BodyModel* model) : state_(state), model_(model) {}

  const std::string& name() const { return model_->name; }
  int index() const { return model_->body; }
  std::size_t node_count() const { return static_cast<std::size_t>(state_->body(index()).count); }
  /// Global index of node 0 in the state.
  int first_node() const { return state_->body(index()).first; }
  BodyModelKind kind() const { return model_->kind; }
  const BodyModel& model() const { return *model_; }

  std::span<const Vec3> positions() const { return state_->range(state_->positions, index()); }
  std::span<Vec3> positions() { return state_->range(state_->positions, index()); }
  std::span<const Vec3> velocities() const { return state_->range(state_->velocities, index()); }
  std::span<Vec3> velocities() { return state_->range(state_->velocities, index()); }
  std::span<const Vec3> rest_positions() const {
    return state_->range(state_->rest_positions, index());
  }
  std::span<const double> masses() const { return state_->range(state_->masses, index()); }
  std::span<const double> inverse_masses() const {
    return state_->range(state_->inverse_masses, index());
  }
  const std::vector<core::Tetrahedron>& tets() const { return model_->mesh.tets; }
  /// Boundary triangles, outward, in body-local node numbers.
  const std::vector<core::Triangle>& surface_faces() const { return model_->surface; }
  /// Distinct tet edges (the distance terms or springs).
  std::size_t edge_count() const;

  /// Largest distance in m of any node from its rest position.
  double max_displacement() const;
  /// Centre of mass in m, now and at rest.
  Vec3 centre_of_mass() const;
  Vec3 rest_centre_of_mass() const;

 private:
  SimulationState* state_;
  const BodyModel* model_;
};

}  // namespace viscera::sim
