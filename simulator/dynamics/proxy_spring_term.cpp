#include "simulator/dynamics/proxy_spring_term.h"

#include <algorithm>

namespace viscera::sim {

ProxySpringTerm::ProxySpringTerm(std::vector<std::shared_ptr<const BodyModel>> models,
                                 double stiffness, const SimulationState& state, const Vec3& tip)
    : models_(std::move(models)), proxy_(stiffness), tip_(tip) {
  proxy_.reset(tip);
  rebuild(state, -1);
}

void ProxySpringTerm::rebuild(const SimulationState& state, int changed_body) {
  // Each body's surface in its own node numbers, with its adjacency, is kept: a cut searches
  // the adjacency of the cut body's surface only, then the parts are joined in global numbers.
  body_surfaces_.resize(models_.size(), ProxySurface(std::vector<core::Triangle>{}));
  std::vector<int> node_offsets;
  face_body_.clear();
  face_first_.clear();
  surface_nodes_.clear();
  int faces = 0;
  for (std::size_t b = 0; b < models_.size(); ++b) {
    const auto& m = models_[b];
    if (changed_body < 0 || m->body == changed_body) body_surfaces_[b] = ProxySurface(m->surface);
    const int first = state.body(m->body).first;
    node_offsets.push_back(first);
    face_first_.push_back(faces);
    faces += static_cast<int>(m->surface.size());
    face_body_.insert(face_body_.end(), m->surface.size(), m->body);
    for (const auto& f : m->surface)
      for (const int v : f)
        surface_nodes_.push_back(first + v);
  }
  std::sort(surface_nodes_.begin(), surface_nodes_.end());
  surface_nodes_.erase(std::unique(surface_nodes_.begin(), surface_nodes_.end()),
                       surface_nodes_.end());
  surface_ = std::make_unique<ProxySurface>(ProxySurface::joined(body_surfaces_, node_offsets));
  // A new surface: the proxy starts free where it is and finds its contact at the next step.
  proxy_.reset(proxy_.proxy());
  active_ = {-1, -1, -1};
  tree_built_ = false;
}

void ProxySpringTerm::topology_changed(const SimulationState& state, int body) {
  rebuild(state, body);
}

void ProxySpringTerm::prepare(const SimulationState& state, const StepContext& context) {
  if (!tree_built_) {
    tree_ = ProxySurfaceTree(surface_->faces(), state.positions);
    tree_built_ = true;
  }
  proxy_.update(tip_, *surface_, state.positions, &tree_);
  // The wall may have swung over the tip since the last step (it overshoots when pushed and
  // springs back): that is a contact the path test alone misses. Once per step, at its first
  // (sub-)step: the tip moves between steps, not between an explicit integrator's sub-steps.
  if (context.step != recaptured_at_step_) {
    recaptured_at_step_ = context.step;
    proxy_.recapture(*surface_, state.positions, &tree_);
  }
  if (proxy_.in_contact()) {
    const auto& c = proxy_.contact();
    active_ = surface_->faces()[static_cast<std::size_t>(c.triangle)];
    weight_ = c.barycentric;
  } else {
    active_ = {-1, -1, -1};
  }
}

void ProxySpringTerm::after_step(const SimulationState& state) {
  tree_.mark_moved();
  if (proxy_.in_contact()) proxy_.update(tip_, *surface_, state.positions);
}

double ProxySpringTerm::energy(std::span<const Vec3> x) const {
  if (active_[0] < 0) return 0.0;
  const Vec3 p =
      weight_[0] * x[active_[0]] + weight_[1] * x[active_[1]] + weight_[2] * x[active_[2]];
  return 0.5 * proxy_.stiffness() * (p - tip_).squaredNorm();
}

double ProxySpringTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                                   std::span<Vec3> f) const {
  if (active_[0] < 0) return 0.0;
  const Vec3 p =
      weight_[0] * x[active_[0]] + weight_[1] * x[active_[1]] + weight_[2] * x[active_[2]];
  const Vec3 pull = proxy_.stiffness() * (p - tip_);
  for (int k = 0; k < 3; ++k)
    f[active_[k]] -= weight_[k] * pull;
  return 0.5 * proxy_.stiffness() * (p - tip_).squaredNorm();
}

void ProxySpringTerm::declare_blocks(BlockPattern& pattern) const {
  // The active triangle's nodes are joined by tet edges, whose blocks every body's internal
  // terms declare: the proxy never changes the structure (structure_changed() stays false).
  if (active_[0] >= 0) pattern.add_clique(active_);
}

void ProxySpringTerm::add_stiffness(std::span<const Vec3>, double scale, bool,
                                    BlockSparseMatrix& m) const {
  if (active_[0] < 0) return;
  const double k = scale * proxy_.stiffness();
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b)
      m.add_symmetric(active_[a], active_[b], (k * weight_[a] * weight_[b]) * Mat3::Identity());
}

core::BoundingBox ProxySpringTerm::reach() const {
  // The proxy only gets nearer the tip: its walk goes to the surface point nearest the tip,
  // and a released proxy tests the path to the tip. So it stays within |tip − proxy| of the
  // tip, and the surfaces move by at most the margin.
  const double radius = (tip_ - proxy_.proxy()).norm() + kReachMargin;
  core::BoundingBox box;
  box.add(tip_ - Vec3::Constant(radius));
  box.add(tip_ + Vec3::Constant(radius));
  return box;
}

int ProxySpringTerm::touched_body() const {
  return proxy_.in_contact() ? face_body_[static_cast<std::size_t>(proxy_.contact().triangle)] : -1;
}

int ProxySpringTerm::touched_body_triangle() const {
  if (!proxy_.in_contact()) return -1;
  const int body = touched_body();
  return proxy_.contact().triangle - face_first_[static_cast<std::size_t>(body)];
}

}  // namespace viscera::sim
