#pragma once
/// Assessment metrics of a session (seed 000 §11): duration, path length and economy of
/// movement, tool–tissue contacts (count and time), and the forces felt.

#include <nlohmann/json.hpp>

#include "core/math_types.h"

namespace viscera::sim {

/// Metrics accumulated step by step. Lengths in m, times in s, forces in N.
class SessionMetrics {
 public:
  /// Records one step of `dt` s: the tip position, the force on the instrument and whether the
  /// instrument touches tissue.
  void record(const core::Vec3& tip, const core::Vec3& force, bool in_contact, double dt);

  double duration() const { return duration_; }
  double path_length() const { return path_length_; }
  /// Straight distance from the first to the last tip position over the path length, in
  /// [0, 1]: 1 is the most economical movement.
  double economy() const;
  int contacts() const { return contacts_; }  ///< separate touches (onsets of contact)
  double contact_time() const { return contact_time_; }
  double max_force() const { return max_force_; }
  /// Mean force magnitude while in contact.
  double mean_force() const { return contact_time_ > 0.0 ? force_time_ / contact_time_ : 0.0; }

  nlohmann::json to_json() const;

 private:
  bool started_ = false;
  core::Vec3 first_ = core::Vec3::Zero(), last_ = core::Vec3::Zero();
  double duration_ = 0.0, path_length_ = 0.0, contact_time_ = 0.0, force_time_ = 0.0, max_force_ = 0.0;
  int contacts_ = 0;
  bool was_in_contact_ = false;
};

}  // namespace viscera::sim
