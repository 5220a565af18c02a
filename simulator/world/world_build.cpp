#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "simulator/dynamics/attachment_term.h"
#include "simulator/dynamics/authored_terms.h"
#include "simulator/dynamics/connection_spring_term.h"
#include "simulator/dynamics/gravity_term.h"
#include "simulator/dynamics/kismo_spring_term.h"
#include "simulator/dynamics/teschner_terms.h"
#include "simulator/world/world.h"

namespace viscera::sim {
namespace {

int body_named(const std::vector<std::shared_ptr<BodyModel>>& models, const std::string& id,
               const std::string& pointer) {
  for (const auto& m : models)
    if (m->name == id) return m->body;
  throw core::InputError("connected object \"" + id + "\" has no simulated body",
                         {"", pointer, id});
}

void check_node(const BodyModel& model, int node, const std::string& pointer) {
  if (node < 0 || static_cast<std::size_t>(node) >= model.mesh.nodes.size()) {
    throw core::InputError("node " + std::to_string(node) + " is not a node of body \"" +
                               model.name + "\" (" + std::to_string(model.mesh.nodes.size()) +
                               " nodes)",
                           {"", pointer, model.name});
  }
}

bool is_pathology(const core::Scenario& scenario, const std::string& id) {
  const core::SceneObject* object = scenario.find_object(id);
  return object != nullptr && object->role == core::ObjectRole::Pathology;
}

}  // namespace

void World::build_terms(const core::Scenario& scenario) {
  // Internal forces of every body, each element with its own tet's material.
  for (const auto& model : models_) {
    if (model->kind == BodyModelKind::CellAgent) continue;  // an AgentTissueTerm, below
    if (model->kind == BodyModelKind::KismoMassSpring) {
      terms_.push_back(std::make_unique<KismoSpringTerm>(model, state_));
      continue;
    }
    terms_.push_back(std::make_unique<TeschnerDistanceTerm>(model, state_));
    auto area = std::make_unique<TeschnerAreaTerm>(model, state_);
    if (!area->terms().triangles.empty()) terms_.push_back(std::move(area));
    terms_.push_back(std::make_unique<TeschnerVolumeTerm>(model, state_));
  }
  // Connections: a pathology's base is bound to its host's tets (it moves with the wall); other
  // connected objects are held by linear springs between their knots (seed 001 §3.3).
  std::vector<ConnectionSpring> springs;
  std::vector<Attachment> attachments;
  for (std::size_t c = 0; c < scenario.connections.size(); ++c) {
    const core::Connection& connection = scenario.connections[c];
    const std::string pointer = "/scenario/connections/" + std::to_string(c);
    if (!(connection.stiffness > 0.0) || !std::isfinite(connection.stiffness)) {
      throw core::InputError("connection stiffness must be positive and finite",
                             {"", pointer + "/stiffness", connection.id});
    }
    const int a = body_named(models_, connection.object_a, pointer + "/object_a");
    const int b = body_named(models_, connection.object_b, pointer + "/object_b");
    const bool attach_b = is_pathology(scenario, connection.object_b);
    const bool attach_a = !attach_b && is_pathology(scenario, connection.object_a);
    for (std::size_t p = 0; p < connection.node_pairs.size(); ++p) {
      const auto [node_a, node_b] = connection.node_pairs[p];
      const std::string pair_pointer = pointer + "/node_pairs/" + std::to_string(p);
      check_node(*models_[static_cast<std::size_t>(a)], node_a, pair_pointer + "/0");
      check_node(*models_[static_cast<std::size_t>(b)], node_b, pair_pointer + "/1");
      const Vec3& rest_a =
          models_[static_cast<std::size_t>(a)]->mesh.nodes[static_cast<std::size_t>(node_a)];
      const Vec3& rest_b =
          models_[static_cast<std::size_t>(b)]->mesh.nodes[static_cast<std::size_t>(node_b)];
      if (attach_a || attach_b) {
        Attachment attachment;
        attachment.body = attach_b ? b : a;
        attachment.node = attach_b ? node_b : node_a;
        attachment.host = attach_b ? a : b;
        attachment.host_rest = attach_b ? rest_b : rest_a;
        attachment.stiffness = connection.stiffness;
        attachment.tet = locate_in_tets(models_[static_cast<std::size_t>(attachment.host)]->mesh,
                                        attachment.host_rest, attachment.weight);
        if (attachment.tet < 0)
          throw core::InputError("host object has no tets to attach to",
                                 {"", pointer, connection.id});
        attachments.push_back(attachment);
      } else {
        springs.push_back({a, node_a, b, node_b, connection.stiffness, (rest_b - rest_a).norm()});
      }
    }
  }
  if (!springs.empty())
    terms_.push_back(std::make_unique<ConnectionSpringTerm>(std::move(springs), state_));
  const std::vector<std::shared_ptr<const BodyModel>> models(models_.begin(), models_.end());
  if (!attachments.empty())
    terms_.push_back(std::make_unique<AttachmentTerm>(std::move(attachments), models, state_));
  if (contact_stiffness_ > 0.0) {
    auto contact = std::make_unique<BodyContactTerm>(models, contact_stiffness_, state_);
    contact_ = contact.get();
    terms_.push_back(std::move(contact));
  }
  terms_.push_back(std::make_unique<GravityTerm>(gravity_, state_));
  // What else was authored: plasticity, tearing, cell agents, motility, pulse (issue 16).
  for (auto& term : authored_terms(scenario, state_, models_, terms_, time_step_))
    terms_.push_back(std::move(term));
}

void World::topology_changed(int body, const BodyTopology& topology) {
  if (body < 0 || body >= static_cast<int>(models_.size()))
    throw core::UsageError("topology_changed: no body " + std::to_string(body));
  BodyModel& model = *models_[static_cast<std::size_t>(body)];
  const core::TetMesh& mesh = topology.rest_mesh;
  core::check_tet_mesh(mesh, "body " + model.name);
  const std::size_t n = mesh.nodes.size();
  if (topology.positions.size() != n || topology.origin.size() != n ||
      topology.tet_parent.size() != mesh.tets.size() ||
      (!topology.released.empty() && topology.released.size() != n))
    throw core::InputError("new topology's arrays do not match its mesh",
                           {"", "", "body " + model.name});
  // Per-tet materials follow the parent tets.
  std::vector<int> tet_material(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const int parent = topology.tet_parent[t];
    if (parent < 0 || static_cast<std::size_t>(parent) >= model.tet_material.size())
      throw core::InputError("new tet " + std::to_string(t) + " has no parent tet",
                             {"", "", "body " + model.name});
    tet_material[t] = model.tet_material[static_cast<std::size_t>(parent)];
  }
  // Node data: velocities and fixed flags carried by the origin weights; masses from the mesh,
  // else lumped from each new tet's material density (total mass = Σ density × volume).
  const auto old_velocity = state_.range(state_.velocities, body);
  const auto old_inverse = state_.range(state_.inverse_masses, body);
  BodyNodeData data;
  data.rest = mesh.nodes;
  data.positions = topology.positions;
  data.velocities.assign(n, Vec3::Zero());
  data.fixed.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const NodeOrigin& o = topology.origin[i];
    bool fixed = true, any = false;
    for (int k = 0; k < 4; ++k) {
      if (o.node[k] < 0 || o.weight[k] == 0.0) continue;
      if (static_cast<std::size_t>(o.node[k]) >= old_velocity.size())
        throw core::InputError(
            "new node " + std::to_string(i) + " comes from a node the body does not have",
            {"", "", "body " + model.name});
      any = true;
      data.velocities[i] += o.weight[k] * old_velocity[static_cast<std::size_t>(o.node[k])];
      fixed = fixed && old_inverse[static_cast<std::size_t>(o.node[k])] == 0.0;
    }
    data.fixed[i] = any && fixed ? 1 : 0;
  }
  if (!mesh.fixed.empty()) data.fixed = mesh.fixed;
  if (!mesh.node_mass.empty()) {
    data.masses = mesh.node_mass;
  } else {
    data.masses.assign(n, 0.0);
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const double quarter = model.materials[static_cast<std::size_t>(tet_material[t])].density *
                             core::signed_volume(mesh, static_cast<int>(t)) / 4.0;
      for (const int v : mesh.tets[t])
        data.masses[static_cast<std::size_t>(v)] += quarter;
    }
  }
  model.mesh = mesh;
  model.surface = mesh.surface_faces.empty() ? core::boundary_faces(mesh.tets) : mesh.surface_faces;
  model.tet_material = std::move(tet_material);
  state_.replace_body_nodes(body, data);
  if (!topology.released.empty()) {
    for (const auto& term : terms_) {
      if (auto* attachments = dynamic_cast<AttachmentTerm*>(term.get()))
        attachments->release(body, topology.released);
      else if (auto* springs = dynamic_cast<ConnectionSpringTerm*>(term.get()))
        springs->release(body, topology.released);
    }
  }
  for (const auto& term : terms_)
    term->topology_changed(state_, body);
  integrator_->body_topology_changed(state_, term_pointers(), body);
  integrator_stale_ = false;
  refresh_views();
}

}  // namespace viscera::sim
