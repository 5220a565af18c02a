#include "simulator/session/session_report.h"

#include <algorithm>

#include "core/json_eigen.h"

namespace viscera::sim {

PeriodScore period_score(const SessionMetrics& m, double force_warning,
                         std::optional<double> resection) {
  if (!(m.path_length() > 0.0) || !(m.duration() > 0.0)) {
    return {std::nullopt,
            "the instrument never moved, so nothing of the trainee's work can be assessed"};
  }
  std::vector<double> terms;
  if (m.tasks_available() > 0)
    terms.push_back(static_cast<double>(m.tasks_completed()) / m.tasks_available());
  terms.push_back(m.economy());
  if (resection) terms.push_back(std::clamp(*resection, 0.0, 1.0));
  if (m.view_time() > 0.0) terms.push_back(m.view_quality());
  terms.push_back(1.0 - std::clamp(m.contact_time() / m.duration(), 0.0, 1.0));
  if (force_warning > 0.0)
    terms.push_back(1.0 - std::clamp(m.max_force() / force_warning, 0.0, 1.0));
  double sum = 0.0;
  for (const double t : terms)
    sum += t;
  return {100.0 * sum / static_cast<double>(terms.size()), ""};
}

namespace {

/// A number (a score, a depth) or null where there is none.
nlohmann::json number_or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

/// The reason of an absent score, or null beside a score.
nlohmann::json reason_json(const std::optional<double>& score, const std::string& reason) {
  return score ? nlohmann::json(nullptr) : nlohmann::json(reason);
}

nlohmann::json energy_json(const SessionReport& r) {
  nlohmann::json series = {
      {"time", nlohmann::json::array()},    {"kinetic", nlohmann::json::array()},
      {"elastic", nlohmann::json::array()}, {"gravitational", nlohmann::json::array()},
      {"total", nlohmann::json::array()},   {"max_displacement", nlohmann::json::array()}};
  for (const auto& s : r.samples) {
    series["time"].push_back(s.time);
    series["kinetic"].push_back(s.kinetic);
    series["elastic"].push_back(s.elastic);
    series["gravitational"].push_back(s.gravitational);
    series["total"].push_back(s.total());
    series["max_displacement"].push_back(s.max_displacement);
  }
  return series;
}

nlohmann::json path_json(const SessionReport& r) {
  nlohmann::json path = {
      {"time", nlohmann::json::array()},       {"tip", nlohmann::json::array()},
      {"force", nlohmann::json::array()},      {"wall_distance", nlohmann::json::array()},
      {"in_contact", nlohmann::json::array()}, {"step", nlohmann::json::array()}};
  for (const auto& p : r.path) {
    path["time"].push_back(p.time);
    path["tip"].push_back(p.tip);
    path["force"].push_back(p.force);
    path["wall_distance"].push_back(p.wall_distance);
    path["in_contact"].push_back(p.in_contact);
    path["step"].push_back(p.step);
  }
  return path;
}

/// The distension fluid over time (s, Pa, m³), or null without fluid.
nlohmann::json fluid_series_json(const SessionReport& r) {
  if (!r.fluid) return nullptr;
  nlohmann::json series = {{"time", nlohmann::json::array()},
                           {"pressure", nlohmann::json::array()},
                           {"deficit", nlohmann::json::array()},
                           {"bled", nlohmann::json::array()},
                           {"intravasated", nlohmann::json::array()}};
  for (const FluidSample& s : r.fluid_series) {
    series["time"].push_back(s.time);
    series["pressure"].push_back(s.pressure);
    series["deficit"].push_back(s.deficit);
    series["bled"].push_back(s.bled);
    series["intravasated"].push_back(s.intravasated);
  }
  return series;
}

/// The cuts (issue 17 §5) in s, m³ and degrees, or null when the instrument cannot cut.
nlohmann::json cutting_json(const SessionReport& r) {
  if (!r.cutting) return nullptr;
  const CuttingSummary& c = *r.cutting;
  std::vector<double> times = c.cut_seconds;
  std::sort(times.begin(), times.end());
  const auto median = [&]() -> nlohmann::json {
    if (times.empty()) return nullptr;
    const std::size_t h = times.size() / 2;
    return times.size() % 2 == 1 ? times[h] : 0.5 * (times[h - 1] + times[h]);
  };
  nlohmann::json bodies = nlohmann::json::array();
  for (const auto& b : c.bodies) {
    bodies.push_back({{"body", b.body},
                      {"initial_volume", b.initial_volume},
                      {"resected_volume", b.resected_volume},
                      {"resected_fraction", b.resected_fraction()},
                      {"chips", b.chips},
                      {"debris", b.debris},
                      {"chips_retrieved", b.chips_retrieved},
                      {"retrieved_volume", b.retrieved_volume}});
  }
  const auto angle = [&](double degrees) -> nlohmann::json {
    return c.cuts > 0 ? nlohmann::json(degrees) : nlohmann::json(nullptr);
  };
  return {{"sweeps", c.sweeps},
          {"cuts", c.cuts},
          {"released_in_tissue", c.released_in_tissue},
          {"tets_created", c.tets_created},
          {"cut_time_median", median()},
          {"cut_time_max", times.empty() ? nlohmann::json(nullptr) : nlohmann::json(times.back())},
          {"min_dihedral_before", angle(c.min_dihedral_before_degrees)},
          {"min_dihedral_after", angle(c.min_dihedral_after_degrees)},
          {"volume_before", c.volume_before},
          {"volume_after", c.volume_after},
          {"deepest_wall_cut", number_or_null(c.deepest_wall_cut)},
          {"wall_thickness_at_deepest_cut", number_or_null(c.wall_thickness_at_deepest_cut)},
          {"healthy_wall_removed", number_or_null(c.healthy_wall_removed)},
          {"pathologies", bodies}};
}

/// m³ of blood every bleeding source let out.
double blood_loss(const SessionReport& r) {
  double bled = 0.0;
  if (r.bleeding)
    for (const auto& source : *r.bleeding)
      bled += source.bled;
  return bled;
}

/// The distension fluid's balance in m³ and Pa, or null without fluid.
nlohmann::json fluid_json(const SessionReport& r) {
  if (!r.fluid) return nullptr;
  const FluidTotals& f = *r.fluid;
  return {{"used", f.used},
          {"drained", f.drained},
          {"absorbed", f.absorbed},
          {"bled", f.bled},
          {"intravasated", f.intravasated},
          {"deficit", f.deficit()},
          {"max_pressure", f.max_pressure},
          {"mean_pressure", f.mean_pressure()},
          {"final_pressure", r.final_cavity_pressure},
          {"time_above_absorption_threshold", f.time_above_threshold}};
}

/// The bleeding of the session's cuts (m³, s), or null when nothing could cut: blood loss,
/// fluid taken up through the opened vessels, the episodes (one per source) and how long the
/// controlled ones took to control.
nlohmann::json bleeding_json(const SessionReport& r) {
  if (!r.bleeding) return nullptr;
  double blood_loss = 0.0, intravasated = 0.0, control_time = 0.0;
  int controlled = 0;
  nlohmann::json sources = nlohmann::json::array();
  for (const fluid::BleedingSource& s : *r.bleeding) {
    blood_loss += s.bled;
    intravasated += s.intravasated;
    const char* stop = s.stop == fluid::BleedingStop::Coagulated ? "coagulated"
                       : s.stop == fluid::BleedingStop::Clipped  ? "clipped"
                       : s.stop == fluid::BleedingStop::Clotted  ? "clotted"
                                                                 : "bleeding";
    if (s.stop != fluid::BleedingStop::Bleeding) {
      ++controlled;
      control_time += s.stopped_at - s.opened_at;
    }
    nlohmann::json source = {
        {"kind", s.capillary ? "capillary" : "vessel"},
        {"opened_at", s.opened_at},
        {"state", stop},
        {"stopped_at", s.stop == fluid::BleedingStop::Bleeding ? nlohmann::json(nullptr)
                                                               : nlohmann::json(s.stopped_at)},
        {"bled", s.bled},
        {"intravasated", s.intravasated}};
    if (s.capillary) {
      source["area"] = s.area;
    } else {
      source["vessel_tree"] = s.vessel_tree;
      source["segment"] = s.segment;
      source["radius"] = s.radius;
      source["level"] = s.level;
    }
    sources.push_back(std::move(source));
  }
  return {{"blood_loss", blood_loss},
          {"intravasated", intravasated},
          {"episodes", r.bleeding->size()},
          {"controlled", controlled},
          {"mean_time_to_control",
           controlled > 0 ? nlohmann::json(control_time / controlled) : nlohmann::json(nullptr)},
          {"sources", sources}};
}

/// The cavity's flow and how the blood clouded the view (m³, s), or null without a flow.
nlohmann::json cavity_flow_json(const SessionReport& r) {
  if (!r.cavity_flow) return nullptr;
  const CavityFlowSummary& f = *r.cavity_flow;
  return {{"flow_steps", f.flow_steps},
          {"relabellings", f.relabellings},
          {"cell_size", f.cell_size},
          {"fluid_cells", f.fluid_cells},
          {"mean_pressure_iterations", f.mean_pressure_iterations},
          {"view_obscured_time", f.view_obscured_time},
          {"lowest_transmission", f.lowest_transmission},
          {"obscured_threshold", f.obscured_threshold},
          {"blood_released", f.blood_released},
          {"blood_in_cavity", f.blood_in_cavity},
          {"blood_drained", f.blood_drained},
          {"blood_lost", f.blood_lost},
          {"particles", f.particles},
          {"air_bubbles_admitted", f.air_bubbles_admitted},
          {"air_bubbles_flushed", f.air_bubbles_flushed},
          {"air_bubbles_at_end", f.air_bubbles_at_end},
          {"debris_released", f.debris_released},
          {"debris_flushed", f.debris_flushed},
          {"debris_at_end", f.debris_at_end}};
}

/// How a threaded session kept time, or null for a headless one.
nlohmann::json realtime_json(const SessionReport& r) {
  if (!r.realtime) return nullptr;
  const RealtimeStats& s = *r.realtime;
  nlohmann::json out = {{"wall_time", s.wall_time},
                        {"physics_steps", s.physics_steps},
                        {"late_steps", s.late_steps},
                        {"max_lag", s.max_lag},
                        {"frames", s.frames},
                        {"view_fps", s.view_fps},
                        {"render_scale", s.render_scale},
                        {"lowest_render_scale", s.lowest_render_scale},
                        {"device", nullptr},
                        {"left_device", nullptr}};
  if (s.device) {
    out["device"] = {{"poses", s.device_poses},
                     {"feedback", s.device_feedback},
                     {"feedback_rate", s.feedback_rate},
                     {"real_time_priority", s.device_real_time}};
  }
  if (s.left_device) {
    out["left_device"] = {{"poses", s.left_device_poses},
                          {"feedback", s.left_device_feedback},
                          {"feedback_rate", s.left_feedback_rate},
                          {"real_time_priority", s.left_device_real_time}};
  }
  return out;
}

}  // namespace

nlohmann::json report_to_json(const SessionReport& r) {
  nlohmann::json contacts = {{"colliding_points", nlohmann::json::array()},
                             {"max_penetration", nlohmann::json::array()}};
  for (const auto& s : r.samples) {
    contacts["colliding_points"].push_back(s.colliding_points);
    contacts["max_penetration"].push_back(s.max_penetration);
  }
  contacts["max_penetration_overall"] = r.max_penetration;
  contacts["stiffness"] = r.contact_stiffness;
  nlohmann::json bodies = nlohmann::json::array();
  for (const auto& b : r.bodies) {
    bodies.push_back({{"name", b.name},
                      {"nodes", b.nodes},
                      {"edges", b.edges},
                      {"tets", b.tets},
                      {"surface_triangles", b.surface_triangles},
                      {"max_displacement", b.max_displacement},
                      {"centre_of_mass_drop", b.centre_of_mass_drop}});
  }
  nlohmann::json tasks = nlohmann::json::array();
  for (const auto& t : r.tasks) {
    nlohmann::json task = {{"id", t.id},     {"name", t.name},       {"kind", t.kind},
                           {"step", t.step}, {"substep", t.substep}, {"status", t.status}};
    if (t.completed_at >= 0.0) task["completed_at"] = t.completed_at;
    if (t.best >= 0.0) task["best"] = t.best;
    if (!t.note.empty()) task["note"] = t.note;
    tasks.push_back(task);
  }
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : r.procedure_steps) {
    nlohmann::json step = {{"id", s.id},
                           {"name", s.name},
                           {"metrics", s.metrics.to_json()},
                           {"score", number_or_null(s.score)},
                           {"score_reason", reason_json(s.score, s.score_reason)}};
    step["started_at"] =
        s.started_at >= 0.0 ? nlohmann::json(s.started_at) : nlohmann::json(nullptr);
    step["ended_at"] = s.ended_at >= 0.0 ? nlohmann::json(s.ended_at) : nlohmann::json(nullptr);
    steps.push_back(step);
  }
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : r.events)
    events.push_back({{"time", e.time}, {"kind", e.kind}, {"message", e.message}});
  return {{"format", "viscera-session-report"},
          {"version", 3},
          {"package", r.package},
          {"procedure", r.procedure},
          {"instrument_kind", r.instrument},
          {"steps", r.steps},
          {"simulated_time", r.simulated_time},
          {"wall_time", r.wall_time},
          {"time_step", r.time_step},
          {"substeps", r.substeps},
          {"settling", {{"steps", r.settle_steps}, {"at_rest", r.settled_at_rest}}},
          {"time_limit", r.time_limit},
          {"force_warning", r.force_warning},
          {"real_time_factor", r.wall_time > 0.0 ? r.simulated_time / r.wall_time : 0.0},
          {"units",
           {{"time", "s"}, {"energy", "J"}, {"length", "m"}, {"force", "N"}, {"angle", "deg"}}},
          {"energy", energy_json(r)},
          {"max_displacement", r.max_displacement},
          {"contacts", contacts},
          {"bodies", bodies},
          {"tasks", tasks},
          {"procedure_steps", steps},
          {"instrument", r.has_instrument ? r.metrics.to_json() : nlohmann::json(nullptr)},
          {"metrics", r.metrics.to_json()},
          {"score", number_or_null(r.score)},
          {"score_reason", reason_json(r.score, r.score_reason)},
          {"path", path_json(r)},
          {"fluid", fluid_json(r)},
          {"fluid_series", fluid_series_json(r)},
          {"cutting", cutting_json(r)},
          {"bleeding", bleeding_json(r)},
          {"laparoscopy", r.laparoscopy ? laparoscopy_json(*r.laparoscopy, blood_loss(r))
                                        : nlohmann::json(nullptr)},
          {"distension_flow", cavity_flow_json(r)},
          {"realtime", realtime_json(r)},
          {"end_reason", r.end_reason},
          {"events", events},
          {"checkpoints", r.checkpoints.size()},
          {"final_state_hash", r.final_state_hash}};
}

}  // namespace viscera::sim
