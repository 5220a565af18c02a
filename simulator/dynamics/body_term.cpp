#include "simulator/dynamics/body_term.h"

namespace viscera::sim {

void BodyTerm::initialise(const SimulationState& state) {
  first_ = state.body(model_->body).first;
  build(state, first_);
}

void BodyTerm::topology_changed(const SimulationState& state, int body) {
  const int first = state.body(model_->body).first;
  if (body == model_->body) {
    first_ = first;
    build(state, first_);
    return;
  }
  if (first != first_) shift(first - first_);
  first_ = first;
}

}  // namespace viscera::sim
