#include "simulator/session/session_metrics.h"

#include <algorithm>

namespace viscera::sim {

void SessionMetrics::record(const core::Vec3& tip, const core::Vec3& force, bool in_contact, double dt) {
  if (!started_) {
    first_ = last_ = tip;
    started_ = true;
  }
  path_length_ += (tip - last_).norm();
  last_ = tip;
  duration_ += dt;
  if (in_contact) {
    if (!was_in_contact_) ++contacts_;
    contact_time_ += dt;
    force_time_ += force.norm() * dt;
  }
  max_force_ = std::max(max_force_, force.norm());
  was_in_contact_ = in_contact;
}

double SessionMetrics::economy() const {
  return path_length_ > 0.0 ? std::min(1.0, (last_ - first_).norm() / path_length_) : 1.0;
}

nlohmann::json SessionMetrics::to_json() const {
  return {{"duration", duration_},          {"path_length", path_length_},   {"economy_of_movement", economy()},
          {"contacts", contacts_},          {"contact_time", contact_time_}, {"max_force", max_force_},
          {"mean_contact_force", mean_force()}};
}

}  // namespace viscera::sim
