// The laparoscopic tools of a session (issue 19 §3): a SessionRunner part kept apart from the
// step loop in session_runner.cpp.
#include <algorithm>

#include "simulator/dynamics/proxy_spring_term.h"
#include "simulator/dynamics/pulse_waves.h"
#include "simulator/dynamics/vessel_wave_paths.h"
#include "simulator/session/session_runner.h"

namespace viscera::sim {

namespace {
/// A clip or coagulated spot closes a vessel whose wall lies within this of it, m (half a jaw's
/// width beyond the wall: the jaws close on what they touch).
constexpr double kVesselReach = 1.5e-3;
/// Bipolar forceps seal bleeding within this of the tissue between their jaws, m.
constexpr double kBipolarReach = 3e-3;
}  // namespace

core::Vec3 SessionRunner::instrument_force() const {
  core::Vec3 force = tissue_ ? tissue_->force() : core::Vec3::Zero();
  if (tools_) force += tools_->force(world_);
  return force;
}

core::Vec3 SessionRunner::second_port_force() const {
  if (!tools_ || second_proxy_ == nullptr || !state_.second.inserted) return core::Vec3::Zero();
  return second_proxy_->proxy().force() + tools_->force(world_, 1);
}

void SessionRunner::move_second_port() {
  if (!tools_) return;
  const InstrumentState port = in_port(state_, 1);
  if (!state_.second.inserted) {
    // Taken out: the tool slides back along its shaft, once, out of the abdomen.
    if (second_proxy_ != nullptr && !second_withdrawn_)
      second_proxy_->set_tip(second_proxy_->tip() - 0.1 * second_axis_);
    second_withdrawn_ = true;
    return;
  }
  second_withdrawn_ = false;
  second_axis_ = port.axis;
  const core::Vec3 touch = hinge(port, tools_->options());
  if (second_proxy_ == nullptr) {
    std::vector<std::shared_ptr<const BodyModel>> models(world_.models().begin(),
                                                         world_.models().end());
    auto proxy = std::make_unique<ProxySpringTerm>(std::move(models), options_.instrument_stiffness,
                                                   world_.state(), touch);
    second_proxy_ = proxy.get();
    world_.add_term(std::move(proxy));
  }
  second_proxy_->set_tip(touch);
  // A world asleep wakes when this tool touches, as it does for the working port's.
  if (world_.asleep()) {
    second_proxy_->prepare(world_.state(),
                           StepContext{world_.time(), world_.time_step(), world_.steps() + 1});
    if (second_proxy_->proxy().in_contact()) world_.wake();
  }
}

void SessionRunner::move_tissue() {
  if (!tools_) {
    tissue_->move(state_, world_.time_step());
    return;
  }
  InstrumentState touching = state_;
  touching.tip = hinge(state_, tools_->options());
  tissue_->move(touching, world_.time_step());
}

void SessionRunner::start_tears(std::vector<int> bodies) {
  tears_ = std::make_unique<TissueTears>(world_, std::move(bodies));
  tears_->cut_visible_surfaces(visible_.get());
  tears_->on_crack([this](int body, const cutting::TopologyChange& change, double time) {
    const std::size_t before = bleeding_->sources().size();
    start_bleeding(body, change, time);
    if (tools_) pulse_opened_arteries(before);
  });
}

void SessionRunner::start_tools(const core::Scenario& scenario) {
  tools_ = std::make_unique<LaparoscopicTools>(world_);
  if (!visible_) visible_ = std::make_unique<VisibleSurfaces>(scenario, world_);
  tools_->cut_visible_surfaces(visible_.get());
  report_.laparoscopy.emplace();
  if (!bleeding_) start_bleeding_sources(scenario);
  tools_->on_cut([this](int body, const cutting::TopologyChange& change, double time) {
    const std::size_t before = bleeding_->sources().size();
    start_bleeding(body, change, time);
    pulse_opened_arteries(before);
    // Coagulated tissue has no open capillaries: ooze from a cut through it is sealed at once
    // (bipolar coagulation before the cut is what keeps a sterilisation dry).
    const auto& coagulated = tools_->coagulated()[static_cast<std::size_t>(body)];
    const auto positions = world_.state().range(world_.state().positions, body);
    for (std::size_t i = before; i < bleeding_->sources().size(); ++i) {
      const fluid::BleedingSource& source = bleeding_->sources()[i];
      const bool dry = std::all_of(source.nodes.begin(), source.nodes.end(), [&](int n) {
        return coagulated[static_cast<std::size_t>(n)] != 0;
      });
      if (!source.capillary || !dry) continue;
      const core::Vec3 site = fluid::site_position(source, positions);
      std::vector<core::Vec3> sites;
      for (const fluid::BleedingSource& s : bleeding_->sources())
        sites.push_back(
            fluid::site_position(s, world_.state().range(world_.state().positions, s.body)));
      bleeding_->coagulate(site, 1e-9, sites, time);
    }
  });
  tools_->on_clip([this](int body, const ClipTerm& clip, double time) {
    core::Vec3 rest = core::Vec3::Zero();
    for (const NodeReference& r : clip.nodes())
      rest += r.rest / static_cast<double>(clip.nodes().size());
    stop_pulse_near(body, rest, kVesselReach, time, "a clip");
    // A clip between the root and a cut stops that cut's arterial bleeding (seed 001 §5.1.2).
    if (!bleeding_) return;
    int stopped = 0;
    for (const core::VesselTree& tree : hosted_trees_[static_cast<std::size_t>(body)])
      stopped += bleeding_->clip_at(body, tree, rest, kVesselReach, time);
    if (stopped > 0)
      report_.events.push_back(
          {time, "bleeding-clipped", std::to_string(stopped) + " bleeding source(s) clipped"});
  });
  tools_->on_coagulation([this](int body, const std::vector<int>& nodes, double time) {
    const auto positions = world_.state().range(world_.state().positions, body);
    const auto rest = world_.state().range(world_.state().rest_positions, body);
    core::Vec3 at = core::Vec3::Zero(), at_rest = core::Vec3::Zero();
    for (const int n : nodes) {
      at += positions[static_cast<std::size_t>(n)] / static_cast<double>(nodes.size());
      at_rest += rest[static_cast<std::size_t>(n)] / static_cast<double>(nodes.size());
    }
    seal_bleeding_near(at, kBipolarReach, time);
    stop_pulse_near(body, at_rest, kVesselReach, time, "coagulated tissue");
  });
}

void SessionRunner::pulse_opened_arteries(std::size_t first) {
  // The mean arterial pressure of 85 mmHg swings by the pulse pressure of 40 mmHg (120/80):
  // a = 20 / 85. The wave reaches the opening arc / velocity after each beat.
  constexpr double kAmplitude = 20.0 / 85.0;
  for (std::size_t i = first; i < bleeding_->sources().size(); ++i) {
    const fluid::BleedingSource& source = bleeding_->sources()[i];
    if (source.capillary) continue;
    for (const core::ActiveDeformation& deformation : scenario_.active_deformations) {
      const auto* pulse = std::get_if<core::PulseSpec>(&deformation.spec);
      if (pulse == nullptr || pulse->vessel_tree != source.vessel_tree) continue;
      for (const core::VesselTree& tree : hosted_trees_[static_cast<std::size_t>(source.body)]) {
        if (tree.id != source.vessel_tree) continue;
        const auto& seg = tree.segments[static_cast<std::size_t>(source.segment)];
        const core::Vec3 site = fluid::site_position(
            source, world_.state().range(world_.state().rest_positions, source.body));
        const double along =
            std::max(0.0, (site - seg.proximal).dot((seg.distal - seg.proximal).normalized()));
        const double arc =
            proximal_arc_lengths(tree)[static_cast<std::size_t>(source.segment)] + along;
        bleeding_->set_pulse(i, 60.0 / pulse->heart_rate, arc / pulse->pulse_velocity, kAmplitude);
      }
    }
  }
}

void SessionRunner::follow_tools(double time) {
  tools_->follow(state_, world_, time, world_.time_step(), *report_.laparoscopy, report_.events);
}

void SessionRunner::seal_bleeding_near(const core::Vec3& point, double reach, double time) {
  if (!bleeding_ || bleeding_->sources().empty()) return;
  std::vector<core::Vec3> sites;
  sites.reserve(bleeding_->sources().size());
  for (const fluid::BleedingSource& source : bleeding_->sources())
    sites.push_back(
        fluid::site_position(source, world_.state().range(world_.state().positions, source.body)));
  const int sealed = bleeding_->coagulate(point, reach, sites, time);
  if (sealed > 0) {
    report_.events.push_back(
        {time, "bleeding-coagulated", std::to_string(sealed) + " bleeding source(s) sealed"});
    stop_pulse_at_sealed_vessels(time);
  }
}

void SessionRunner::stop_pulse_near(int body, const core::Vec3& rest_point, double reach,
                                    double time, const std::string& what) {
  for (const auto& term : world_.terms()) {
    auto* pulse = dynamic_cast<PulseWaves*>(term.get());
    if (pulse == nullptr || pulse->model().body != body) continue;
    if (pulse->occlude_nearest(rest_point, reach))
      report_.events.push_back(
          {time, "pulse-stopped",
           "the pulse of vessel tree \"" + pulse->vessel_tree() + "\" stops at " + what});
  }
}

}  // namespace viscera::sim
