#include "textures/active_deformation_specs.h"

#include <cmath>
#include <map>
#include <set>

#include "core/error.h"

namespace viscera::textures {
namespace {

// Ranges. Pulse: resting to maximal heart rates; arterial pulse wave velocities of 4–12 m/s
// (aorta to peripheral arteries) with margins; wall forces of the KisMo force model are small.
// Motility: peristalsis and uterine contractions move tissue millimetres to centimetres at
// 0.05–0.3 Hz (stomach 3/min, small bowel up to 12/min).
constexpr double kHeartRateMin = 20.0, kHeartRateMax = 250.0;            // bpm, error outside
constexpr double kHeartRateUsualMin = 40.0, kHeartRateUsualMax = 180.0;  // bpm, warning outside
constexpr double kPulseVelocityMax = 30.0;                               // m/s
constexpr double kPulseVelocityUsualMin = 2.0, kPulseVelocityUsualMax = 20.0;
constexpr double kWallForceMax = 10.0;           // N
constexpr double kAmplitudeMax = 0.05;           // m
constexpr double kWaveSpeedMax = 1.0;            // m/s
constexpr double kFrequencyMax = 5.0;            // Hz
constexpr double kFrequencyUsualMax = 1.0;       // Hz
constexpr double kContractionIntervalMin = 0.1;  // s

void check(std::vector<SpecIssue>& issues, bool ok, const std::string& pointer,
           const std::string& message, bool error = true) {
  if (!ok) issues.push_back({pointer, message, error});
}

bool finite(double v) {
  return std::isfinite(v);
}

}  // namespace

double longest_wave_path(const core::VesselTree& tree) {
  std::vector<double> reach(tree.segments.size(), 0.0);
  double longest = 0.0;
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const auto& s = tree.segments[i];
    const double length = (s.distal - s.proximal).norm();
    const bool has_parent = s.parent >= 0 && s.parent < static_cast<int>(i);
    reach[i] = (has_parent ? reach[s.parent] : 0.0) + length;
    longest = std::max(longest, reach[i]);
  }
  return longest;
}

std::vector<SpecIssue> validate_pulse_spec(const core::PulseSpec& spec,
                                           const core::Scenario* scenario, const std::string& p) {
  std::vector<SpecIssue> issues;
  check(issues,
        finite(spec.heart_rate) && spec.heart_rate >= kHeartRateMin &&
            spec.heart_rate <= kHeartRateMax,
        p + "/heart_rate", "heart rate must lie in [20, 250] beats per minute");
  check(issues,
        !(spec.heart_rate >= kHeartRateMin && spec.heart_rate <= kHeartRateMax) ||
            (spec.heart_rate >= kHeartRateUsualMin && spec.heart_rate <= kHeartRateUsualMax),
        p + "/heart_rate", "heart rate outside the usual 40–180 beats per minute", false);
  check(issues,
        finite(spec.pulse_velocity) && spec.pulse_velocity > 0.0 &&
            spec.pulse_velocity <= kPulseVelocityMax,
        p + "/pulse_velocity", "mean pulse velocity must lie in (0, 30] m/s");
  check(issues,
        !(spec.pulse_velocity > 0.0 && spec.pulse_velocity <= kPulseVelocityMax) ||
            (spec.pulse_velocity >= kPulseVelocityUsualMin &&
             spec.pulse_velocity <= kPulseVelocityUsualMax),
        p + "/pulse_velocity", "pulse velocity outside the arterial 2–20 m/s", false);
  check(issues,
        finite(spec.wall_force) && spec.wall_force > 0.0 && spec.wall_force <= kWallForceMax,
        p + "/wall_force", "wall force must lie in (0, 10] N");
  check(issues, !spec.vessel_tree.empty(), p + "/vessel_tree",
        "a pulse needs the id of a vessel tree");
  if (scenario && !spec.vessel_tree.empty()) {
    const core::VesselTree* tree = nullptr;
    for (const auto& t : scenario->vessel_trees) {
      if (t.id == spec.vessel_tree) tree = &t;
    }
    check(issues, tree != nullptr, p + "/vessel_tree",
          "unknown vessel tree \"" + spec.vessel_tree + "\"");
    if (tree) {
      check(issues, !tree->segments.empty(), p + "/vessel_tree", "the vessel tree has no segments");
      // Seed 001 §5.1.1: with a fast heart and a slow wave, a new wave starts while others
      // still travel, and all of them are deleted: distal vessels would never pulse.
      if (spec.pulse_velocity > 0.0 && spec.heart_rate > 0.0) {
        const double transit = longest_wave_path(*tree) / spec.pulse_velocity;
        const double period = 60.0 / spec.heart_rate;
        check(issues, transit <= period, p + "/pulse_velocity",
              "a wave needs " + std::to_string(transit) +
                  " s to cross the tree but beats come every " + std::to_string(period) +
                  " s; distal vessels will not pulse",
              false);
      }
    }
  }
  return issues;
}

std::vector<SpecIssue> validate_motility_spec(const core::MotilitySpec& m, const std::string& p) {
  std::vector<SpecIssue> issues;
  check(issues,
        finite(m.amplitude_mean) && m.amplitude_mean >= 0.0 && m.amplitude_mean <= kAmplitudeMax,
        p + "/amplitude_mean", "amplitude mean must lie in [0, 0.05] m");
  check(issues,
        finite(m.amplitude_variance) && m.amplitude_variance >= 0.0 &&
            std::sqrt(std::max(m.amplitude_variance, 0.0)) <= kAmplitudeMax,
        p + "/amplitude_variance",
        "amplitude variance must be ≥ 0 m² with a deviation of at most 0.05 m");
  check(issues,
        !(m.amplitude_variance > 0.0) ||
            std::sqrt(m.amplitude_variance) <= std::max(m.amplitude_mean, 0.0),
        p + "/amplitude_variance",
        "amplitude deviation exceeds the mean: many impulses will reverse", false);
  check(issues, finite(m.wave_speed) && m.wave_speed >= 0.0 && m.wave_speed <= kWaveSpeedMax,
        p + "/wave_speed", "wave speed must lie in [0, 1] m/s");
  check(issues, m.wave_direction.allFinite() && std::abs(m.wave_direction.norm() - 1.0) <= 1e-6,
        p + "/wave_direction", "wave direction must be a unit vector");
  check(issues, finite(m.frequency) && m.frequency > 0.0 && m.frequency <= kFrequencyMax,
        p + "/frequency", "frequency must lie in (0, 5] Hz");
  check(issues, !(m.frequency > kFrequencyUsualMax && m.frequency <= kFrequencyMax),
        p + "/frequency", "organ motility above 1 Hz is unusual (peristalsis: 0.05–0.3 Hz)", false);
  check(issues,
        finite(m.frequency_disturbance) && m.frequency_disturbance >= 0.0 &&
            m.frequency_disturbance < std::max(m.frequency, 0.0),
        p + "/frequency_disturbance", "frequency disturbance must lie in [0, frequency)");
  check(issues, finite(m.contraction_interval_mean) && m.contraction_interval_mean >= 0.0,
        p + "/contraction_interval_mean",
        "contraction interval mean must be ≥ 0 s (0: no contractions)");
  check(issues,
        !(m.contraction_interval_mean > 0.0) ||
            m.contraction_interval_mean >= kContractionIntervalMin,
        p + "/contraction_interval_mean", "contractions closer than 0.1 s apart are not impulses");
  check(issues, finite(m.contraction_interval_variance) && m.contraction_interval_variance >= 0.0,
        p + "/contraction_interval_variance", "contraction interval variance must be ≥ 0 s²");
  check(issues, m.contraction_interval_mean > 0.0 || m.contraction_interval_variance == 0.0,
        p + "/contraction_interval_variance",
        "a timing variance needs contractions (a positive mean interval)");
  check(issues,
        !(m.contraction_interval_variance > 0.0) ||
            std::sqrt(m.contraction_interval_variance) <= m.contraction_interval_mean,
        p + "/contraction_interval_variance",
        "interval deviation exceeds the mean: intervals will be clipped", false);
  return issues;
}

std::vector<SpecIssue> validate_active_deformations(const core::Scenario& scenario) {
  std::vector<SpecIssue> issues;
  std::set<std::string> ids;
  std::map<std::string, std::size_t> pulse_of_tree;
  for (std::size_t i = 0; i < scenario.active_deformations.size(); ++i) {
    const auto& a = scenario.active_deformations[i];
    const std::string base = "/scenario/active_deformations/" + std::to_string(i);
    check(issues, !a.id.empty() && ids.insert(a.id).second, base + "/id",
          "ids must be present and unique");
    check(issues, scenario.find_object(a.target_object) != nullptr, base + "/target_object",
          "unknown object \"" + a.target_object + "\"");
    if (const auto* pulse = std::get_if<core::PulseSpec>(&a.spec)) {
      for (auto& issue : validate_pulse_spec(*pulse, &scenario, base + "/pulse"))
        issues.push_back(std::move(issue));
      const auto [it, fresh] = pulse_of_tree.emplace(pulse->vessel_tree, i);
      check(issues, fresh, base + "/pulse/vessel_tree",
            "vessel tree already pulses in active deformation " + std::to_string(it->second));
    } else {
      for (auto& issue :
           validate_motility_spec(std::get<core::MotilitySpec>(a.spec), base + "/motility")) {
        issues.push_back(std::move(issue));
      }
    }
  }
  return issues;
}

namespace {

void throw_first_error(const std::vector<SpecIssue>& issues, const std::string& id) {
  for (const auto& issue : issues) {
    if (issue.error) throw core::ValidationError(issue.message, {"", issue.json_pointer, id});
  }
}

}  // namespace

core::ActiveDeformation make_pulse(const std::string& id, const std::string& target_object,
                                   const core::VesselTree& tree, double heart_rate_bpm,
                                   double pulse_velocity, double wall_force) {
  core::PulseSpec spec;
  spec.vessel_tree = tree.id;
  spec.heart_rate = heart_rate_bpm;
  spec.pulse_velocity = pulse_velocity;
  spec.wall_force = wall_force;
  core::Scenario only_tree;
  only_tree.vessel_trees.push_back(tree);
  throw_first_error(validate_pulse_spec(spec, &only_tree, "/pulse"), id);
  return {id, target_object, spec};
}

core::ActiveDeformation make_motility(const std::string& id, const std::string& target_object,
                                      const core::MotilitySpec& spec) {
  throw_first_error(validate_motility_spec(spec, "/motility"), id);
  return {id, target_object, spec};
}

}  // namespace viscera::textures
