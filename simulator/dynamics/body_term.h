#pragma once
/// Base of the force terms that act inside one body: they keep global node indices and follow
/// their body's node range when another body's topology changes.

#include <memory>

#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

class BodyTerm : public ForceTerm {
 public:
  explicit BodyTerm(std::shared_ptr<const BodyModel> model) : model_(std::move(model)) {}
  const BodyModel& model() const { return *model_; }
  int body() const override { return model_->body; }
  /// Own body: rebuild from the (updated) model; another body: shift indices if the range moved.
  void topology_changed(const SimulationState& state, int body) override;

 protected:
  /// Builds the elements from model() with global indices starting at `first`.
  virtual void build(const SimulationState& state, int first) = 0;
  /// Adds `delta` to every global node index held.
  virtual void shift(int delta) = 0;
  /// Call from the derived constructor.
  void initialise(const SimulationState& state);

 private:
  std::shared_ptr<const BodyModel> model_;
  int first_ = 0;
};

}  // namespace viscera::sim
