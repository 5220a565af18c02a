#include "simulator/runtime/local_contact_model.h"

#include <unordered_map>

namespace viscera::sim {

ContactSurface::ContactSurface(const std::vector<core::Triangle>& faces) {
  std::unordered_map<int, int> index;
  faces_.reserve(faces.size());
  for (const core::Triangle& face : faces) {
    core::Triangle compact{};
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = index.emplace(face[k], static_cast<int>(nodes_.size()));
      if (added) nodes_.push_back(face[k]);
      compact[k] = it->second;
    }
    faces_.push_back(compact);
  }
}

void ContactSurface::gather(std::span<const core::Vec3> body_positions,
                            std::vector<core::Vec3>& out) const {
  out.resize(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    out[i] = body_positions[static_cast<std::size_t>(nodes_[i])];
}

LocalContactModel::LocalContactModel(const ContactSurface& surface, double stiffness)
    : surface_(surface.faces()), has_surface_(!surface.empty()), proxy_(stiffness) {}

core::Vec3 LocalContactModel::force_at(const core::Vec3& tip) {
  if (!placed_) {
    proxy_.reset(tip);
    placed_ = true;
  }
  if (tissue_ == nullptr) return core::Vec3::Zero();
  if (!has_surface_ || tissue_->surface.size() < 3) return tissue_->force;
  proxy_.update(tip, surface_, tissue_->surface);
  // The wall may have moved over the tip since the last pose; the physics step saw it.
  if (!proxy_.in_contact() && tissue_->in_contact) proxy_.recapture(surface_, tissue_->surface);
  return proxy_.force();
}

}  // namespace viscera::sim
