#include "core/modelling/model_scene.h"

#include <map>
#include <set>

#include "core/error.h"
#include "core/meshing/tet_mesher.h"
#include "core/modelling/object_connectivity.h"

namespace viscera::core {

SurfaceMesh tessellate_model(const ModelDocument& model, Progress& progress) {
  check_model(model);
  switch (model.kind) {
    case ModelKind::Ball:
      return tessellate_ball(model.ball);
    case ModelKind::Flat: {
      FlatPrimitive flat = model.flat;
      // The layers make the slab of a layered flat; its own slab would be a second one.
      if (model.layering) flat.open = true;
      return tessellate_flat(flat);
    }
    case ModelKind::Pipe:
      return tessellate_pipe_network(model.pipe, progress);
  }
  return {};
}

SceneObject build_model_object(const ModelDocument& model, Progress& progress) {
  SceneObject object;
  object.id = model.id;
  object.name = model.name.empty() ? model.id : model.name;
  object.role = model.role;
  object.group = model.group;
  object.surface = tessellate_model(model, progress);
  const Material material = model.material.value_or(Material{});
  if (model.material) object.material = model.material->id;

  if (model.layering) {
    const ModelLayering& layering = *model.layering;
    if (layering.mass_spring) {
      object.body_kind = BodyKind::MassSpring;
      object.body = mass_spring_body(layered_mass_spring_net(object.surface, layering.layers));
    } else {
      object.body_kind = BodyKind::TetMesh;
      TetMeshingOptions meshing;
      meshing.cell_size = layering.cell_size;
      object.body = layered_shell_tets(object.surface, layering.layers, meshing, progress);
    }
    // Both bodies start with the surface's vertices (layer 0).
    object.embedding = embed_leading_nodes(object.body, object.surface.vertices.size());
  } else if (is_closed_and_consistently_oriented(object.surface)) {
    object.body_kind = BodyKind::TetMesh;
    object.body = mesh_closed_surface(object.surface, {}, progress);
    object.embedding = embed_points(object.surface.vertices, object.body);
  } else {
    if (!model.fixed.empty())
      throw ValidationError("an open sheet without layers has no body to fix",
                            {"", "/fixed", model.id});
    return object;
  }

  object.body.node_mass = lumped_node_masses(object.body, material.density);
  object.body.fixed.assign(object.body.nodes.size(), 0);
  for (std::size_t r = 0; r < model.fixed.size(); ++r) {
    const FixedRegion& region = model.fixed[r];
    int held = 0;
    for (std::size_t n = 0; n < object.body.nodes.size(); ++n) {
      if ((object.body.nodes[n] - region.center).norm() <= region.radius) {
        object.body.fixed[n] = 1;
        ++held;
      }
    }
    if (held == 0)
      throw ValidationError("fixed region " + std::to_string(r) + " holds no node of the body",
                            {"", "/fixed/" + std::to_string(r), model.id});
  }
  return object;
}

Scenario build_model_scenario(const std::vector<ModelDocument>& models, Progress& progress) {
  Scenario scenario;
  scenario.metadata.name = models.size() == 1 ? models.front().name : "modelled scene";
  scenario.metadata.description = "Objects modelled from KisMo's ball, flat and pipe types.";
  scenario.metadata.author = "viscera model";
  std::set<std::string> ids;
  for (const auto& model : models) {
    if (!ids.insert(model.id).second)
      throw UsageError("two models have the id \"" + model.id + "\"");
    if (model.material) {
      const auto [it, added] = scenario.materials.emplace(model.material->id, *model.material);
      if (!added && !(it->second == *model.material))
        throw ValidationError(
            "material \"" + model.material->id + "\" has different constants in two models",
            {"", "/material", model.id});
    }
  }
  for (const auto& model : models) {
    progress.check_cancelled();
    scenario.objects.push_back(build_model_object(model, progress));
  }
  for (const auto& model : models) {
    for (std::size_t c = 0; c < model.connections.size(); ++c) {
      const ModelConnection& request = model.connections[c];
      const std::string where = "/connections/" + std::to_string(c);
      if (!ids.count(request.object))
        throw ValidationError(
            "connects to \"" + request.object + "\", which is not among the models",
            {"", where, model.id});
      Connection connection =
          connect_objects(scenario, model.id, request.object, request.distance, request.stiffness);
      if (connection.node_pairs.empty())
        throw ValidationError("no knots of \"" + model.id + "\" and \"" + request.object +
                                  "\" lie within " + std::to_string(request.distance) + " m",
                              {"", where, model.id});
      scenario.connections.push_back(std::move(connection));
    }
  }
  scenario.session.metrics = {"max_displacement", "kinetic_energy", "potential_energy"};
  scenario.provenance.template_name = "model";
  return scenario;
}

}  // namespace viscera::core
