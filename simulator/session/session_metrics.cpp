#include "simulator/session/session_metrics.h"

#include <algorithm>

namespace viscera::sim {

void SessionMetrics::record(const core::Vec3& tip, const core::Vec3& force, bool in_contact,
                            double dt, double inflow) {
  if (!started_) {
    first_ = last_ = tip;
    started_ = true;
  }
  path_length_ += (tip - last_).norm();
  last_ = tip;
  duration_ += dt;
  inflow_time_ += inflow * dt;
  if (in_contact) {
    if (!was_in_contact_) ++contacts_;
    contact_time_ += dt;
    force_time_ += force.norm() * dt;
  }
  max_force_ = std::max(max_force_, force.norm());
  was_in_contact_ = in_contact;
}

void SessionMetrics::record_view(bool good, double dt) {
  view_time_ += dt;
  if (good) good_view_time_ += dt;
}

double SessionMetrics::economy() const {
  if (!(path_length_ > 0.0)) return 1.0;
  double straight = 0.0;
  core::Vec3 from = first_;
  for (const auto& m : milestones_) {
    straight += (m - from).norm();
    from = m;
  }
  straight += (last_ - from).norm();
  return std::min(1.0, straight / path_length_);
}

nlohmann::json SessionMetrics::to_json() const {
  return {{"duration", duration_},
          {"path_length", path_length_},
          {"economy_of_movement", economy()},
          {"contacts", contacts_},
          {"contact_time", contact_time_},
          {"max_force", max_force_},
          {"mean_contact_force", mean_force()},
          {"surface_seen", surface_seen()},
          {"view_quality", view_quality()},
          {"inflow_open_time", inflow_time_},
          // m³ from the distension-fluid balance; null when the scenario simulates no fluid.
          {"distension_fluid_used",
           fluid_simulated_ ? nlohmann::json(fluid_used_) : nlohmann::json(nullptr)},
          {"tasks_completed", tasks_completed_},
          {"tasks_available", tasks_available_}};
}

}  // namespace viscera::sim
