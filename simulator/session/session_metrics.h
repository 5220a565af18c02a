#pragma once
/// Assessment metrics of a session or of one of its steps (seed 000 §11): duration, path length
/// and economy of movement, tool–wall collisions (count and contact time), the forces felt,
/// the surface seen by the camera, the quality of the view and the valves' use.

#include <nlohmann/json.hpp>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// Metrics accumulated step by step. Lengths in m, times in s, forces in N.
class SessionMetrics {
 public:
  /// Records one physics step of `dt` s: the tip position, the force on the instrument, whether
  /// the instrument touches tissue and the inflow valve opening (0…1).
  void record(const core::Vec3& tip, const core::Vec3& force, bool in_contact, double dt,
              double inflow = 0.0);
  /// Starts the path at `tip` (the tool's position when the period begins).
  void start_at(const core::Vec3& tip) {
    first_ = last_ = tip;
    started_ = true;
  }
  /// Records one look through the optics covering `dt` s: `good` when the surface ahead is at a
  /// usable viewing distance and the lens is not against the wall.
  void record_view(bool good, double dt);
  /// A point the procedure required the tool to pass (where a task completed): economy of
  /// movement measures the path against the straight lines through these.
  void add_milestone(const core::Vec3& tip) { milestones_.push_back(tip); }
  /// Fraction of the inspected surface seen at the start and end of the period.
  void set_coverage(double at_start, double at_end) {
    coverage_start_ = at_start;
    coverage_end_ = at_end;
  }
  /// Adds `volume` m³ of distension fluid delivered by the pump (DistensionBalance): from the
  /// first call on the period reports the fluid used instead of null.
  void record_fluid(double volume) {
    fluid_used_ += volume;
    fluid_simulated_ = true;
  }
  void set_tasks(int completed, int available) {
    tasks_completed_ = completed;
    tasks_available_ = available;
  }

  double duration() const { return duration_; }
  double path_length() const { return path_length_; }
  /// Length of the straight path from the first tip through every milestone to the last tip,
  /// over the path length, in [0, 1]: 1 is the most economical movement.
  double economy() const;
  int contacts() const { return contacts_; }  ///< separate touches (onsets of contact)
  double contact_time() const { return contact_time_; }
  double max_force() const { return max_force_; }
  /// Mean force magnitude while in contact.
  double mean_force() const { return contact_time_ > 0.0 ? force_time_ / contact_time_ : 0.0; }
  /// Seconds of looking through the optics recorded (record_view).
  double view_time() const { return view_time_; }
  /// Share of the viewing time with a good view, in [0, 1].
  double view_quality() const { return view_time_ > 0.0 ? good_view_time_ / view_time_ : 0.0; }
  double surface_seen() const { return coverage_end_ - coverage_start_; }  ///< fraction gained
  double coverage_start() const { return coverage_start_; }
  double inflow_open_time() const {
    return inflow_time_;
  }  ///< s of fully open inflow valve (weighted)
  int tasks_completed() const { return tasks_completed_; }
  int tasks_available() const { return tasks_available_; }  ///< tasks that could be detected

  nlohmann::json to_json() const;

 private:
  bool started_ = false;
  core::Vec3 first_ = core::Vec3::Zero(), last_ = core::Vec3::Zero();
  std::vector<core::Vec3> milestones_;
  double duration_ = 0.0, path_length_ = 0.0, contact_time_ = 0.0, force_time_ = 0.0,
         max_force_ = 0.0;
  double view_time_ = 0.0, good_view_time_ = 0.0, inflow_time_ = 0.0, fluid_used_ = 0.0;
  bool fluid_simulated_ = false;
  double coverage_start_ = 0.0, coverage_end_ = 0.0;
  int contacts_ = 0, tasks_completed_ = 0, tasks_available_ = 0;
  bool was_in_contact_ = false;
};

}  // namespace viscera::sim
