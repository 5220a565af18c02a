#include "templates/variability/scenario_variation.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "templates/variability/smooth_deformation.h"

namespace viscera::templates {
namespace {

bool shaped_by_geometry(const core::SceneObject& object) {
  return object.body_kind == core::BodyKind::None || object.body_kind == core::BodyKind::TetMesh ||
         object.body_kind == core::BodyKind::MassSpring;
}

/// Lumped masses from each tet's material density (its layer's, else the object's); the masses
/// stay as they were when a density is unknown.
void recompute_masses(core::SceneObject& object, const core::Scenario& scenario) {
  core::TetMesh& body = object.body;
  if (body.tets.empty() || body.node_mass.size() != body.nodes.size()) return;
  std::vector<double> masses(body.nodes.size(), 0.0);
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    std::string material = object.material;
    if (t < body.tet_labels.size()) {
      const auto layer = object.layer_materials.find(body.tet_labels[t]);
      if (layer != object.layer_materials.end()) material = layer->second;
    }
    const auto found = scenario.materials.find(material);
    if (found == scenario.materials.end()) return;
    const double quarter =
        found->second.density * std::abs(core::signed_volume(body, static_cast<int>(t))) / 4.0;
    for (const int node : body.tets[t])
      masses[static_cast<std::size_t>(node)] += quarter;
  }
  body.node_mass = std::move(masses);
}

/// After the object's points moved: normals, embedding.
void refresh_geometry(core::SceneObject& object) {
  if (!object.surface.normals.empty()) core::compute_vertex_normals(object.surface);
  if (!object.embedding.empty() && !object.body.tets.empty())
    object.embedding = core::embed_points(object.surface.vertices, object.body);
}

/// Mean of the pathology object's nodes paired with its host; `fallback` without a connection.
core::Vec3 attachment_point(const core::Scenario& scenario, const core::Pathology& pathology,
                            const core::SceneObject& object, const core::Vec3& fallback) {
  core::Vec3 sum = core::Vec3::Zero();
  int count = 0;
  for (const auto& c : scenario.connections) {
    const bool a_side = c.object_a == pathology.object && c.object_b == pathology.host_object;
    const bool b_side = c.object_b == pathology.object && c.object_a == pathology.host_object;
    if (!a_side && !b_side) continue;
    for (const auto& pair : c.node_pairs) {
      const int node = a_side ? pair[0] : pair[1];
      if (node < 0 || static_cast<std::size_t>(node) >= object.body.nodes.size()) continue;
      sum += object.body.nodes[static_cast<std::size_t>(node)];
      ++count;
    }
  }
  return count > 0 ? core::Vec3(sum / count) : fallback;
}

}  // namespace

ScenarioDraw vary_scenario(const core::Scenario& scenario, core::Rng& rng,
                           const ScenarioVariation& variation) {
  if (variation.centres < 1) throw core::UsageError("scenario variation needs at least 1 centre");
  if (!(variation.amplitude_fraction >= 0.0) || !(variation.width_fraction > 0.0))
    throw core::UsageError(
        "scenario variation amplitude must not be negative and its width must be positive");
  if (!(variation.pathology_size_spread >= 0.0 && variation.pathology_size_spread < 1.0))
    throw core::UsageError("pathology size spread must lie in [0, 1)");

  core::BoundingBox box;
  for (const auto& object : scenario.objects) {
    if (!shaped_by_geometry(object)) continue;
    for (const auto& v : object.surface.vertices)
      box.add(v);
    for (const auto& v : object.body.nodes)
      box.add(v);
  }
  if (box.empty())
    throw core::InputError("the scenario has no object geometry to vary",
                           {scenario.metadata.name, "", ""});
  const double diagonal = box.size().norm();
  const SmoothDeformation field = SmoothDeformation::random(
      rng, box, variation.centres, variation.amplitude_fraction * diagonal,
      variation.width_fraction * diagonal, variation.max_lipschitz);

  ScenarioDraw draw;
  draw.scenario = scenario;
  core::Scenario& s = draw.scenario;
  draw.drawn = {{"lipschitz_bound", field.lipschitz_bound()},
                {"diagonal", diagonal},
                {"pathology_sizes", nlohmann::json::object()}};

  for (auto& object : s.objects) {
    if (!shaped_by_geometry(object)) continue;
    field.apply(object.surface.vertices);
    field.apply(object.body.nodes);
  }
  for (auto& tree : s.vessel_trees) {
    for (auto& segment : tree.segments) {
      segment.proximal = field.apply(segment.proximal);
      segment.distal = field.apply(segment.distal);
    }
  }
  for (auto& landmark : s.landmarks) {
    if (landmark.normal.norm() > 0.0)
      landmark.normal = field.apply_direction(landmark.position, landmark.normal);
    landmark.position = field.apply(landmark.position);
  }
  for (auto& pathology : s.pathologies)
    pathology.position = field.apply(pathology.position);

  // Pathology sizes, drawn in scenario order whether or not an object holds the geometry.
  for (auto& pathology : s.pathologies) {
    const double spread = variation.pathology_size_spread;
    const double ratio = rng.uniform(1.0 - spread, 1.0 + spread);
    const double from = pathology.size;
    pathology.size *= ratio;
    draw.drawn["pathology_sizes"][pathology.id] = {{"from", from}, {"to", pathology.size}};
    auto object = std::find_if(s.objects.begin(), s.objects.end(),
                               [&](const auto& o) { return o.id == pathology.object; });
    if (object == s.objects.end() || !shaped_by_geometry(*object)) continue;
    const core::Vec3 anchor = attachment_point(s, pathology, *object, pathology.position);
    const auto scale = [&](core::Vec3& p) { p = anchor + ratio * (p - anchor); };
    for (auto& v : object->surface.vertices)
      scale(v);
    for (auto& v : object->body.nodes)
      scale(v);
    scale(pathology.position);
  }

  for (auto& object : s.objects) {
    if (!shaped_by_geometry(object)) continue;
    refresh_geometry(object);
    recompute_masses(object, s);
  }
  return draw;
}

}  // namespace viscera::templates
