#include "exporters/sofa_solver_settings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace viscera::exporters {
namespace {

constexpr double kReferenceGravity = 9.81;  // m/s²
constexpr double kThresholdMargin = 1e-6;   // threshold / smallest pᵀAp
constexpr int kMinIterations = 100;
constexpr int kMaxIterations = 100000;

/// Mean boundary edge length in m of a body.
double mean_surface_edge(const core::TetMesh& body) {
  double sum = 0.0;
  int count = 0;
  for (const auto& f : body_surface(body)) {
    for (int e = 0; e < 3; ++e) {
      sum += (body.nodes[static_cast<std::size_t>(f[(e + 1) % 3])] -
              body.nodes[static_cast<std::size_t>(f[e])])
                 .norm();
      ++count;
    }
  }
  return count > 0 ? sum / count : 0.0;
}

}  // namespace

std::vector<core::Triangle> body_surface(const core::TetMesh& body) {
  return body.surface_faces.empty() ? core::boundary_faces(body.tets) : body.surface_faces;
}

SofaContact sofa_contact(const core::Scenario& scenario, const std::vector<SofaBody>& bodies) {
  SofaContact contact;
  contact.stiffness = scenario.session.contact_stiffness;
  contact.enabled = contact.stiffness > 0.0 && bodies.size() > 1;
  if (!contact.enabled) return contact;
  double edge = std::numeric_limits<double>::infinity();
  for (const auto& body : bodies)
    edge = std::min(edge, mean_surface_edge(body.object->source->body));
  // Contacts start 1/20 of an edge apart (Viscera's start at touching) and pairs are tested
  // from half an edge, more than a node moves in one step at tissue speeds.
  contact.contact_distance = 0.05 * edge;
  contact.alarm_distance = 0.5 * edge;
  contact.model_stiffness = std::sqrt(contact.stiffness * contact.contact_distance);
  return contact;
}

SofaSolverSettings sofa_solver_settings(const core::Scenario& scenario,
                                        const std::vector<SofaBody>& bodies,
                                        const SofaContact& contact) {
  SofaSolverSettings s;
  const double h = scenario.session.time_step;
  // Rayleigh β over the tets of bodies that move, weighted by mass.
  double weighted = 0.0, mass = 0.0, low = std::numeric_limits<double>::infinity(), high = 0.0;
  for (const auto& body : bodies) {
    if (body.all_fixed) continue;
    for (std::size_t t = 0; t < body.tet_mass.size(); ++t) {
      weighted += body.tet_rayleigh[t] * body.tet_mass[t];
      mass += body.tet_mass[t];
      low = std::min(low, body.tet_rayleigh[t]);
      high = std::max(high, body.tet_rayleigh[t]);
    }
  }
  if (mass > 0.0) {
    s.rayleigh_exact = high - low <= 1e-9 * high;
    s.rayleigh_stiffness = s.rayleigh_exact ? high : weighted / mass;
  }
  // Node rows: the body's own stiffness, attachment springs and contact on surface nodes.
  double m_min = std::numeric_limits<double>::infinity(), a_max = 0.0;
  std::vector<std::vector<double>> rows;
  for (const auto& body : bodies)
    rows.push_back(body.node_stiffness);
  for (const core::Connection* connection : exported_connections(scenario, bodies)) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const std::string& id = bodies[b].object->id();
      for (const auto& pair : connection->node_pairs) {
        if (id == connection->object_a)
          rows[b][static_cast<std::size_t>(pair[0])] += 2.0 * connection->stiffness;
        if (id == connection->object_b)
          rows[b][static_cast<std::size_t>(pair[1])] += 2.0 * connection->stiffness;
      }
    }
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const SofaBody& body = bodies[b];
    if (contact.enabled) {
      std::set<int> surface;
      for (const auto& f : body_surface(body.object->source->body))
        surface.insert(f.begin(), f.end());
      for (const int n : surface)
        rows[b][static_cast<std::size_t>(n)] += contact.stiffness;
    }
    std::vector<char> held(body.masses.size(), 0);
    for (const int n : body.fixed)
      held[static_cast<std::size_t>(n)] = 1;
    for (std::size_t i = 0; i < body.masses.size(); ++i) {
      if (held[i]) continue;
      m_min = std::min(m_min, body.masses[i]);
      a_max = std::max(a_max, body.masses[i] + h * (h + s.rayleigh_stiffness) * rows[b][i]);
    }
  }
  if (!std::isfinite(m_min)) {  // nothing moves: CG never runs, keep the limits
    s.smallest_denominator = 0.0;
    s.threshold = 0.0;
    s.iterations = kMinIterations;
    return s;
  }
  const double g = std::max(scenario.session.gravity.norm(), kReferenceGravity);
  const double p = s.tolerance * h * m_min * g;
  s.smallest_denominator = m_min * p * p;
  s.threshold = kThresholdMargin * s.smallest_denominator;
  const double kappa = a_max / m_min;
  const double steps = 0.5 * std::sqrt(kappa) * std::log(2.0 / s.tolerance);
  s.iterations = static_cast<int>(std::clamp(std::ceil(steps), static_cast<double>(kMinIterations),
                                             static_cast<double>(kMaxIterations)));
  return s;
}

}  // namespace viscera::exporters
