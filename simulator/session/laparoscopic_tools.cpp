#include "simulator/session/laparoscopic_tools.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/cutting/fragments.h"
#include "simulator/cutting/hybrid_cut.h"
#include "simulator/dynamics/agent_tissue_term.h"
#include "simulator/dynamics/kismo_spring_term.h"
#include "simulator/session/cut_topology.h"

namespace viscera::sim {

namespace {

int piece_count(const World& world, int body) {
  return static_cast<int>(
      cutting::body_fragments(world.models()[static_cast<std::size_t>(body)]->mesh).size());
}

/// Per-node values of `body` carried over a topology change: each new node takes the value of
/// the old node nearest to it at rest (`old_rest` the rest positions before the change).
template <class T>
std::vector<T> carry_by_rest_position(const std::vector<T>& values,
                                      const std::vector<core::Vec3>& old_rest,
                                      std::span<const core::Vec3> new_rest) {
  std::vector<T> out(new_rest.size(), T{});
  for (std::size_t i = 0; i < new_rest.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < old_rest.size(); ++j) {
      const double d = (old_rest[j] - new_rest[i]).squaredNorm();
      if (d < best) best = d, out[i] = values[j];
    }
  }
  return out;
}

/// Sites of knots at rest (m): knots within 5 mm of one another, transitively.
std::vector<int> coagulation_sites(const std::vector<core::Vec3>& rest, int& sites) {
  std::vector<int> site(rest.size(), -1);
  sites = 0;
  for (std::size_t i = 0; i < site.size(); ++i) {
    if (site[i] >= 0) continue;
    site[i] = sites;
    std::vector<std::size_t> stack{i};
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      for (std::size_t j = 0; j < site.size(); ++j)
        if (site[j] < 0 && (rest[j] - rest[k]).norm() <= 0.005) site[j] = sites, stack.push_back(j);
    }
    ++sites;
  }
  return site;
}

}  // namespace

double coagulated_length(const World& world, int body, const std::vector<core::Vec3>& rest,
                         double jaw_width) {
  int sites = 0;
  const std::vector<int> site = coagulation_sites(rest, sites);
  double length = 0.0;
  for (int s = 0; s < sites; ++s) {
    core::Vec3 centre = core::Vec3::Zero();
    int count = 0;
    for (std::size_t i = 0; i < site.size(); ++i)
      if (site[i] == s) centre += rest[i], ++count;
    centre /= count;
    const core::Vec3 axis = local_axis(world, body, centre, 0.01);
    double lo = 0.0, hi = 0.0;
    for (std::size_t i = 0; i < site.size(); ++i) {
      if (site[i] != s) continue;
      const double along = (rest[i] - centre).dot(axis);
      lo = std::min(lo, along), hi = std::max(hi, along);
    }
    length += hi - lo + jaw_width;
  }
  return length;
}

core::Vec3 hinge(const InstrumentState& state, const LaparoscopicToolOptions& options) {
  if (state.tool == LaparoscopicTool::None) return state.tip;
  if (state.tool == LaparoscopicTool::Hook) return hook_touch_point(state, options.hook);
  return state.tip - options.jaw_length * state.axis;
}

core::Mat3 jaw_frame(const InstrumentState& state) {
  core::Mat3 frame;
  frame.col(0) = state.axis.cross(state.up).normalized();
  frame.col(1) = state.up;
  frame.col(2) = state.axis;
  return frame;
}

core::Vec3 local_axis(const World& world, int body, const core::Vec3& point, double radius) {
  const auto rest = world.state().range(world.state().rest_positions, body);
  core::Vec3 mean = core::Vec3::Zero();
  int count = 0;
  for (const auto& p : rest)
    if ((p - point).norm() <= radius) mean += p, ++count;
  if (count < 2) return core::Vec3::Zero();
  mean /= count;
  core::Mat3 covariance = core::Mat3::Zero();
  for (const auto& p : rest)
    if ((p - point).norm() <= radius) covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<core::Mat3> eigen(covariance);
  return eigen.eigenvectors().col(2).normalized();  // eigenvalues ascending
}

LaparoscopicTools::LaparoscopicTools(World& world, LaparoscopicToolOptions options)
    : options_(options) {
  for (const auto& model : world.models()) {
    if (model->kind == BodyModelKind::CellAgent) continue;
    if (!model->mesh.tets.empty()) bodies_.push_back(model->body);
  }
  for (const auto& term : world.terms())
    if (auto* agents = dynamic_cast<AgentTissueTerm*>(term.get())) agents_.push_back(agents);
  touchable_ = bodies_;
  for (const AgentTissueTerm* agents : agents_)
    touchable_.push_back(agents->model().body);
  const std::size_t count = world.models().size();
  dose_.resize(count);
  coagulated_.resize(count);
  stiffened_.resize(count);
  for (std::size_t b = 0; b < count; ++b) {
    dose_[b].assign(static_cast<std::size_t>(world.state().body(static_cast<int>(b)).count), 0.0);
    coagulated_[b].assign(dose_[b].size(), 0);
  }
  for (int p = 0; p < kInstrumentPorts; ++p) {
    Port& port = ports_.emplace_back(options_.hook);
    auto grasp = std::make_unique<GraspTerm>(options_.grasp_stiffness);
    port.grasp = grasp.get();
    world.add_term(std::move(grasp));
  }
}

std::vector<NodeReference> LaparoscopicTools::tissue_between_jaws(const World& world,
                                                                  const InstrumentState& state,
                                                                  double width) const {
  const SimulationState& s = world.state();
  const core::Mat3 frame = jaw_frame(state);
  struct Candidate {
    int body, node;
    double across, distance;
  };
  std::vector<Candidate> inside;
  for (const int b : touchable_) {
    const BodyNodes& range = s.body(b);
    for (int n = 0; n < range.count; ++n) {
      const auto g = static_cast<std::size_t>(range.first + n);
      if (s.inverse_masses[g] == 0.0) continue;
      const core::Vec3 local = frame.transpose() * (s.positions[g] - state.tip);
      if (local.z() < -options_.jaw_length || local.z() > 0.001) continue;
      if (std::abs(local.y()) > 0.5 * options_.jaw_opening) continue;
      if (std::abs(local.x()) > options_.ring_search) continue;
      inside.push_back({b, n, local.x(), std::hypot(local.x(), local.y())});
    }
  }
  if (inside.empty()) return {};
  // One body: the one whose knot lies nearest the jaws' centre line.
  const auto nearest = std::min_element(inside.begin(), inside.end(),
                                        [](auto& a, auto& b) { return a.distance < b.distance; });
  const int body = nearest->body;
  std::erase_if(inside, [body](const Candidate& c) { return c.body != body; });
  const bool any_within = std::any_of(inside.begin(), inside.end(), [&](const Candidate& c) {
    return std::abs(c.across) <= 0.5 * width;
  });
  // Coarser than the jaws: the knot ring nearest the mid-plane (its knots within 1 mm across).
  double centre = 0.0, half = 0.5 * width;
  if (!any_within) {
    const auto ring = std::min_element(inside.begin(), inside.end(), [](auto& a, auto& b) {
      return std::abs(a.across) < std::abs(b.across);
    });
    centre = ring->across, half = 0.001;
  }
  std::vector<NodeReference> out;
  for (const Candidate& c : inside)
    if (std::abs(c.across - centre) <= half) out.push_back(reference_node(s, c.body, c.node));
  return out;
}

std::vector<NodeReference> LaparoscopicTools::tissue_at_hook(const World& world,
                                                             const InstrumentState& state) const {
  const SimulationState& s = world.state();
  const double reach = options_.hook.coagulation_reach;
  int body = -1;
  double nearest = reach;
  std::vector<NodeReference> out;
  for (const int b : touchable_) {
    const BodyNodes& range = s.body(b);
    for (int n = 0; n < range.count; ++n) {
      const auto g = static_cast<std::size_t>(range.first + n);
      if (s.inverse_masses[g] == 0.0) continue;
      const double d = distance_to_hook(s.positions[g], state, options_.hook);
      if (d <= nearest) nearest = d, body = b;
    }
  }
  if (body < 0) return out;
  // One body, the one the wire touches most closely: its knots within reach of the wire.
  const BodyNodes& range = s.body(body);
  for (int n = 0; n < range.count; ++n) {
    const auto g = static_cast<std::size_t>(range.first + n);
    if (s.inverse_masses[g] != 0.0 &&
        distance_to_hook(s.positions[g], state, options_.hook) <= reach)
      out.push_back(reference_node(s, body, n));
  }
  return out;
}

void LaparoscopicTools::follow(const InstrumentState& state, World& world, double time, double dt,
                               LaparoscopySummary& summary, std::vector<SessionEvent>& events) {
  coagulating_at_.reset();
  follow_port(ports_[0], state, "right", world, time, dt, summary, events);
  if (state.second.inserted)
    follow_port(ports_[1], in_port(state, 1), "left", world, time, dt, summary, events);
  else if (!ports_[1].first)
    withdraw(ports_[1], world, time, events);
  const core::Vec3 up = world.gravity().norm() > 0.0 ? core::Vec3(-world.gravity().normalized())
                                                     : core::Vec3(core::Vec3::UnitZ());
  smoke_.step(time, dt, coagulating_at_, up, camera_pose(state).tip);
  for (int p = 0; p < kInstrumentPorts; ++p) {
    const InstrumentState port = in_port(state, p);
    if ((p == 0 || state.second.inserted) && port.tool == LaparoscopicTool::Suction &&
        port.jaws_closed)
      summary.smoke_puffs_suctioned += smoke_.suck(port.tip, options_.suction_reach, time);
  }
  summary.smoke_time = smoke_.smoke_time();
  summary.peak_lens_fog = smoke_.peak_lens_fog();
  summary.smoke_puffs = smoke_.puffs_emitted();
  refresh_clips(world, summary);
}

void LaparoscopicTools::withdraw(Port& port, World& world, double time,
                                 std::vector<SessionEvent>& events) {
  if (port.grasp->holding()) {
    const int body = port.grasp->held().front().body;
    port.grasp->release();
    world.stiffness_changed(body);
    events.push_back({time, "grasp-released", "the grasper left the abdomen"});
  }
  events.push_back({time, "tool-withdrawn",
                    "the " + std::string(tool_name(port.previous.tool)) + " left the second port"});
  port.first = true;
}

void LaparoscopicTools::follow_port(Port& port, const InstrumentState& state, const char* hand,
                                    World& world, double time, double dt,
                                    LaparoscopySummary& summary,
                                    std::vector<SessionEvent>& events) {
  GraspTerm& grasp = *port.grasp;
  if (port.first) {
    port.previous = state;
    port.first = false;
    if (&port != &ports_[0])
      events.push_back({time, "tool-inserted",
                        "a " + std::string(tool_name(state.tool)) + " entered the second port"});
  }
  const double travel = (state.tip - port.previous.tip).norm();
  summary.path_per_tool[std::string(tool_name(state.tool))] += travel;
  summary.path_per_hand[hand] += travel;
  if (state.tool != port.previous.tool) {
    ++summary.tool_switches;
    if (grasp.holding()) {
      const int body = grasp.held().front().body;
      grasp.release();
      world.stiffness_changed(body);
    }
    events.push_back({time, "tool-changed",
                      std::string(&port == &ports_[0] ? "" : "left hand: ") +
                          std::string(tool_name(port.previous.tool)) + " → " +
                          std::string(tool_name(state.tool))});
  }
  const bool closing =
      state.jaws_closed && (!port.previous.jaws_closed || state.tool != port.previous.tool);
  if (closing) close_jaws(port, state, world, time, summary, events);
  if (!state.jaws_closed && grasp.holding()) {
    const int body = grasp.held().front().body;
    grasp.release();
    world.stiffness_changed(body);
    events.push_back({time, "grasp-released", "the grasper opened"});
  }
  if (grasp.holding()) {
    grasp.move_jaws(state.tip, jaw_frame(state));
    const auto x = std::span<const core::Vec3>(world.state().positions);
    summary.max_grasp_force = std::max(summary.max_grasp_force, grasp.force_on_jaws(x).norm());
    const int body = grasp.held().front().body;
    if (const int torn = grasp.tear_out(x, options_.grasp_slip_force); torn > 0) {
      world.stiffness_changed(body);
      summary.knots_torn_out += torn;
      events.push_back(
          {time, "grasp-torn", std::to_string(torn) + " knot(s) tore out of the grasper's jaws"});
    }
  }
  if (state.tool == LaparoscopicTool::Bipolar && state.jaws_closed && state.coagulation)
    heat(tissue_between_jaws(world, state, options_.jaw_width), world, time, dt, summary, events);
  if (state.tool == LaparoscopicTool::Hook && state.coagulation)
    heat(tissue_at_hook(world, state), world, time, dt, summary, events);
  if (auto sweep = port.hook.follow(state)) cut_with_hook(*sweep, world, time, summary, events);
  // Cutting current vaporises the tissue at the wire: the plume rises from there as well.
  if (port.hook.recording() && !coagulating_at_ && !tissue_at_hook(world, state).empty())
    coagulating_at_ = state.tip;
  port.previous = state;
}

void LaparoscopicTools::close_jaws(Port& port, const InstrumentState& state, World& world,
                                   double time, LaparoscopySummary& summary,
                                   std::vector<SessionEvent>& events) {
  switch (state.tool) {
    case LaparoscopicTool::Grasper: {
      auto held = tissue_between_jaws(world, state, options_.jaw_width);
      if (held.empty()) return;
      const std::string body = world.models()[static_cast<std::size_t>(held[0].body)]->name;
      const int held_body = held[0].body;
      port.grasp->hold(world.state(), std::move(held), state.tip, jaw_frame(state));
      world.stiffness_changed(held_body);
      ++summary.grasps;
      events.push_back({time, "grasp",
                        "the grasper holds " + std::to_string(port.grasp->held().size()) +
                            " knot(s) of " + body});
      return;
    }
    case LaparoscopicTool::ClipApplier:
      place_clip(state, world, time, summary, events);
      return;
    case LaparoscopicTool::Scissors:
      cut(state, world, time, summary, events);
      return;
    case LaparoscopicTool::Bipolar:
    case LaparoscopicTool::Suction:
    case LaparoscopicTool::Hook:
    case LaparoscopicTool::None:
      return;
  }
}

void LaparoscopicTools::place_clip(const InstrumentState& state, World& world, double time,
                                   LaparoscopySummary& summary, std::vector<SessionEvent>& events) {
  auto nodes = tissue_between_jaws(world, state, options_.clip_width);
  if (nodes.size() < 2) {
    events.push_back({time, "clip-missed", "the clip applier closed on no tissue"});
    return;
  }
  const int body = nodes[0].body;
  const auto x = std::span<const core::Vec3>(world.state().positions);
  auto clip = std::make_unique<ClipTerm>(std::move(nodes), state.up, options_.clip_stiffness,
                                         world.state(), options_.clip_closed_gap);
  ClipPlacement placed;
  placed.time = time;
  placed.body = world.models()[static_cast<std::size_t>(body)]->name;
  placed.position = clip->centre(x);
  placed.nodes = static_cast<int>(clip->nodes().size());
  core::Vec3 rest = core::Vec3::Zero();
  for (const NodeReference& r : clip->nodes())
    rest += r.rest;
  placed.rest_position = rest / placed.nodes;
  // Across: the angle between the tube's axis and the jaws' length (the shaft) and closing
  // direction, whichever is nearer the tube (both must cross it).
  const core::Vec3 tube = local_axis(world, body, placed.rest_position, 0.01);
  if (tube.norm() > 0.0) {
    const double along = std::max(std::abs(tube.dot(state.axis)), std::abs(tube.dot(state.up)));
    placed.across_degrees = std::acos(std::clamp(along, 0.0, 1.0)) * 180.0 / std::numbers::pi;
  }
  // The lumen is closed when knots lie on both sides of the clip's centre along the closing
  // direction, each farther out than a third of the knots' mean distance from the centre.
  double lo = 0.0, hi = 0.0, mean = 0.0;
  for (const NodeReference& r : clip->nodes()) {
    const core::Vec3 d = x[static_cast<std::size_t>(r.global(world.state()))] - placed.position;
    lo = std::min(lo, d.dot(state.up)), hi = std::max(hi, d.dot(state.up));
    mean += d.norm() / placed.nodes;
  }
  placed.closes_lumen = hi > mean / 3.0 && -lo > mean / 3.0;
  placed.gap_placed = placed.gap = clip->gap(x);
  clip->close_over(time, options_.clip_closing_time);
  ClipTerm& term = *clip;
  clips_.push_back(clip.get());
  clip_bodies_.push_back(body);
  world.add_term(std::move(clip));
  summary.clips.push_back(placed);
  char text[200];
  std::snprintf(text, sizeof text, "a clip closed on %d knot(s) of %s, %.0f° across it%s",
                placed.nodes, placed.body.c_str(), placed.across_degrees,
                placed.closes_lumen ? "" : " (the lumen is not caught)");
  events.push_back({time, "clip-placed", text});
  if (clip_observer_) clip_observer_(body, term, time);
}

void LaparoscopicTools::refresh_clips(const World& world, LaparoscopySummary& summary) const {
  const auto x = std::span<const core::Vec3>(world.state().positions);
  for (std::size_t k = 0; k < clips_.size() && k < summary.clips.size(); ++k)
    summary.clips[k].gap = clips_[k]->nodes().empty() ? 0.0 : clips_[k]->gap(x);
}

void LaparoscopicTools::cut(const InstrumentState& state, World& world, double time,
                            LaparoscopySummary& summary, std::vector<SessionEvent>& events) {
  const auto between = tissue_between_jaws(world, state, options_.jaw_width);
  if (between.empty()) return;
  const int body = between[0].body;
  const core::Vec3 spread = options_.scissor_spread * state.up;
  if (AgentTissueTerm* agents = agents_of(body)) {
    const std::array<core::Vec3, 3> blade = {hinge(state, options_), state.tip + spread,
                                             state.tip - spread};
    cut_links(*agents, {&blade, 1}, "scissors", world, time, summary, events);
    return;
  }
  const cutting::CutSurface blades =
      cutting::scissor_cut_surface(hinge(state, options_), state.tip + spread, state.tip - spread);
  core::Vec3 centre = core::Vec3::Zero();
  for (const NodeReference& r : between)
    centre += world.state().positions[static_cast<std::size_t>(r.global(world.state()))] /
              static_cast<double>(between.size());
  if (!cut_through(body, blades, centre, "scissors", world, time, summary, events)) {
    const std::string& name = world.models()[static_cast<std::size_t>(body)]->name;
    events.push_back({time, "cut-missed", "the scissors closed on " + name + " but cut no tet"});
  }
}

void LaparoscopicTools::cut_with_hook(const cutting::CutSurface& sweep, World& world, double time,
                                      LaparoscopySummary& summary,
                                      std::vector<SessionEvent>& events) {
  core::Vec3 centre = core::Vec3::Zero();
  for (const core::Vec3& p : sweep.vertices)
    centre += p / static_cast<double>(sweep.vertices.size());
  bool cut_any = false;
  for (const int body : bodies_)
    cut_any = cut_through(body, sweep, centre, "hook", world, time, summary, events) || cut_any;
  std::vector<std::array<core::Vec3, 3>> triangles;
  for (const core::Triangle& t : sweep.triangles)
    triangles.push_back({sweep.vertices[static_cast<std::size_t>(t[0])],
                         sweep.vertices[static_cast<std::size_t>(t[1])],
                         sweep.vertices[static_cast<std::size_t>(t[2])]});
  for (AgentTissueTerm* agents : agents_)
    cut_any = cut_links(*agents, triangles, "hook", world, time, summary, events) || cut_any;
  if (!cut_any)
    events.push_back({time, "cut-missed", "the hook's cutting current swept through no tissue"});
}

bool LaparoscopicTools::cut_through(int body, const cutting::CutSurface& surface,
                                    const core::Vec3& centre, const char* tool, World& world,
                                    double time, LaparoscopySummary& summary,
                                    std::vector<SessionEvent>& events) {
  const BodyModel& model = *world.models()[static_cast<std::size_t>(body)];
  const auto positions = world.state().range(world.state().positions, body);
  const std::vector<core::Vec3> current(positions.begin(), positions.end());
  const auto old_rest_span = world.state().range(world.state().rest_positions, body);
  const std::vector<core::Vec3> old_rest(old_rest_span.begin(), old_rest_span.end());
  TissueCut record;
  record.time = time;
  record.tool = tool;
  record.body = model.name;
  record.position = centre;
  const auto start = std::chrono::steady_clock::now();
  const cutting::TopologyChange change = visible_ != nullptr
                                             ? visible_->cut(body, model.mesh, current, surface, {})
                                             : cutting::hybrid_cut(model.mesh, current, surface);
  if (!change.changed) return false;
  record.pieces_before = piece_count(world, body);  // the body's mesh is the old one still
  world.topology_changed(body, topology_of_cut(change, world.held_nodes(body)));
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record.tets_traversed = change.statistics.tets_traversed;
  record.pieces_after = piece_count(world, body);
  const auto b = static_cast<std::size_t>(body);
  const auto new_rest = world.state().range(world.state().rest_positions, body);
  dose_[b] = carry_by_rest_position(dose_[b], old_rest, new_rest);
  coagulated_[b] = carry_by_rest_position(coagulated_[b], old_rest, new_rest);
  stiffened_[b].clear();
  stiffen_coagulated(world, body);
  // Between two secure clips of the same body: the cut's centre projects inside the segment
  // joining them.
  const auto x = std::span<const core::Vec3>(world.state().positions);
  for (std::size_t i = 0; i < clips_.size() && !record.between_clips; ++i) {
    for (std::size_t j = i + 1; j < clips_.size(); ++j) {
      if (clip_bodies_[i] != body || clip_bodies_[j] != body) continue;
      if (!summary.clips[i].secure() || !summary.clips[j].secure()) continue;
      if (clips_[i]->nodes().empty() || clips_[j]->nodes().empty()) continue;
      const core::Vec3 a = clips_[i]->centre(x), c = clips_[j]->centre(x);
      const double t = (record.position - a).dot(c - a) / std::max((c - a).squaredNorm(), 1e-18);
      if (t > 0.0 && t < 1.0) record.between_clips = true;
    }
  }
  summary.cuts.push_back(record);
  if (cut_observer_) cut_observer_(body, change, time);
  events.push_back({time, std::string(tool) + "-cut",
                    "the " + std::string(tool) + " cut " + model.name + " (" +
                        std::to_string(record.tets_traversed) + " tets traversed" +
                        (record.separated() ? ", divided it" : ", not through") +
                        (record.between_clips ? ", between two clips)" : ")")});
  return true;
}

void LaparoscopicTools::heat(const std::vector<NodeReference>& between, World& world, double time,
                             double dt, LaparoscopySummary& summary,
                             std::vector<SessionEvent>& events) {
  if (between.empty()) return;
  summary.coagulation_time += dt;
  const int body = between[0].body;
  core::Vec3 heated = core::Vec3::Zero();
  for (const NodeReference& r : between)
    heated += world.state().positions[static_cast<std::size_t>(r.global(world.state()))];
  coagulating_at_ = heated / static_cast<double>(between.size());
  const auto b = static_cast<std::size_t>(body);
  std::vector<int> fresh;
  for (const NodeReference& r : between) {
    const auto n = static_cast<std::size_t>(r.node);
    dose_[b][n] += dt;
    if (!coagulated_[b][n] && dose_[b][n] >= options_.coagulation_dose - 1e-12) {
      coagulated_[b][n] = 1;
      fresh.push_back(r.node);
    }
  }
  if (fresh.empty()) return;
  stiffen_coagulated(world, body);
  // The body's coagulated tissue: its knots and their length along the tube, per site (knots
  // farther than 5 mm from every other coagulated knot start a new site).
  const std::string& name = world.models()[b]->name;
  auto it = std::find_if(summary.coagulated.begin(), summary.coagulated.end(),
                         [&](const CoagulatedTissue& c) { return c.body == name; });
  if (it == summary.coagulated.end()) {
    summary.coagulated.push_back({name, 0, 0.0, {}});
    it = std::prev(summary.coagulated.end());
  }
  const auto rest = world.state().range(world.state().rest_positions, body);
  for (const int n : fresh)
    it->rest_positions.push_back(rest[static_cast<std::size_t>(n)]);
  it->nodes = static_cast<int>(it->rest_positions.size());
  it->length = coagulated_length(world, body, it->rest_positions, options_.jaw_width);
  events.push_back(
      {time, "coagulated", std::to_string(fresh.size()) + " knot(s) of " + name + " coagulated"});
  if (coagulation_observer_) coagulation_observer_(body, fresh, time);
}

void LaparoscopicTools::stiffen_coagulated(World& world, int body) {
  const auto b = static_cast<std::size_t>(body);
  const int first = world.state().body(body).first;
  for (const auto& term : world.terms()) {
    auto* springs = dynamic_cast<KismoSpringTerm*>(term.get());
    if (springs == nullptr || springs->model().body != body) continue;
    CubicSprings& s = springs->mutable_springs();
    if (stiffened_[b].size() != s.knots.size()) stiffened_[b].assign(s.knots.size(), 0);
    bool changed = false;
    for (std::size_t k = 0; k < s.knots.size(); ++k) {
      const auto i = static_cast<std::size_t>(s.knots[k][0] - first);
      const auto j = static_cast<std::size_t>(s.knots[k][1] - first);
      if (stiffened_[b][k] || !coagulated_[b][i] || !coagulated_[b][j]) continue;
      for (double& c : s.coefficients[k])
        c *= options_.coagulated_stiffening;
      s.rest_length[k] *= 1.0 - options_.coagulated_shrinkage;
      stiffened_[b][k] = 1;
      changed = true;
    }
    if (changed) world.stiffness_changed(body);
  }
}

core::Vec3 LaparoscopicTools::force(const World& world, int port) const {
  return ports_[static_cast<std::size_t>(port)].grasp->force_on_jaws(world.state().positions);
}

}  // namespace viscera::sim
