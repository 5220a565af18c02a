#include "studio/document/organ_authoring.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/lsystem/lsystem.h"
#include "core/materials/shipped_materials.h"
#include "core/random.h"
#include "templates/geometry/surface_queries.h"
#include "templates/hysteroscopy/uterine_pathologies.h"
#include "templates/template_parts.h"
#include "templates/vessels/cco_vessel_generator.h"
#include "templates/vessels/lsystem_vessel_tree.h"
#include "templates/vessels/perfusion_domain.h"
#include "textures/scenario_baking.h"
#include "textures/texture_preset.h"

namespace viscera::studio {
namespace {

const core::SceneObject& object_of(const core::Scenario& scenario, const std::string& id) {
  const core::SceneObject* object = scenario.find_object(id);
  if (object == nullptr) throw core::UsageError("the scenario has no object \"" + id + "\"");
  if (object->surface.triangles.empty())
    throw core::UsageError("object \"" + id + "\" has no surface");
  return *object;
}

/// Mean edge length of a body's tets in m (the spacing of its knots).
double mean_knot_spacing(const core::TetMesh& body) {
  double sum = 0.0;
  std::size_t edges = 0;
  for (const auto& t : body.tets) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b, ++edges)
        sum += (body.nodes[static_cast<std::size_t>(t[a])] -
                body.nodes[static_cast<std::size_t>(t[b])])
                   .norm();
    }
  }
  return edges == 0 ? 0.0 : sum / static_cast<double>(edges);
}

}  // namespace

TexturedObject bake_object_texture(const core::Scenario& scenario, const std::string& object_id,
                                   const TextureRequest& request, core::Progress& progress) {
  (void)textures::find_texture_preset(request.preset);  // a usage error before any work
  core::Scenario single;
  single.objects.push_back(object_of(scenario, object_id));
  core::TextureSpec spec;
  spec.id = object_id + "-" + request.preset;
  spec.preset = request.preset;
  spec.seed = request.seed;
  spec.width = request.width;
  spec.height = request.height;
  single.textures[spec.id] = spec;
  single.objects.front().texture = spec.id;
  textures::BakedTextures baked = textures::bake_textures_into(single, {}, progress);
  return {single.textures.at(spec.id), std::move(single.objects.front()), std::move(baked.files)};
}

core::VesselTree grow_organ_vessels(const core::Scenario& scenario, const std::string& object_id,
                                    const VesselRequest& request, core::Progress& progress) {
  const core::SceneObject& organ = object_of(scenario, object_id);
  const templates::SurfaceMeshDomain domain(organ.surface, object_id + " surface");
  std::string id = object_id + "-vessels";
  for (int n = 2; std::any_of(scenario.vessel_trees.begin(), scenario.vessel_trees.end(),
                              [&](const auto& t) { return t.id == id; });
       ++n)
    id = object_id + "-vessels-" + std::to_string(n);

  core::VesselTree tree;
  if (request.method == VesselMethod::Cco) {
    templates::CcoOptions options;
    options.terminals = request.terminals;
    options.seed = request.seed;
    options.perfusion_flow = request.flow;
    options.murray_exponent = request.murray_exponent;
    options.tree_id = id;
    options.host_object = object_id;
    tree = templates::grow_cco_tree(domain, options, progress);
  } else {
    // As `viscera vessels --method lsystem`: from the inlet towards the organ's centre, the
    // first branch a quarter of the organ's smallest extent.
    progress.begin_stage("growing the L-system tree", 1);
    const auto grammar = core::Lsystem::parse(templates::kDefaultVesselGrammar, "built-in grammar");
    templates::LsystemVesselOptions options;
    options.generations = request.generations;
    options.seed = request.seed;
    options.total_flow = request.flow;
    options.root_radius = request.root_radius;
    options.turtle.seed = request.seed;
    options.turtle.angle_jitter = 8.0;
    options.domain = &domain;
    const auto box = domain.bounds();
    options.turtle.origin = domain.default_inlet();
    const core::Vec3 inward = (box.center() - options.turtle.origin).normalized();
    options.turtle.heading = inward.allFinite() ? inward : core::Vec3::UnitZ();
    options.turtle.left = options.turtle.heading.unitOrthogonal();
    options.turtle.step = 0.25 * box.size().minCoeff();
    options.tree_id = id;
    options.host_object = object_id;
    tree = templates::lsystem_vessel_tree(grammar, options);
    progress.step();
  }
  tree.id = id;
  tree.host_object = object_id;
  return tree;
}

PathologyParts build_pathology_at(const core::Scenario& scenario, const std::string& host_id,
                                  const core::Vec3& point, const std::string& kind, double size,
                                  std::uint64_t seed, core::Progress& progress) {
  const core::SceneObject& host = object_of(scenario, host_id);
  if (host.body.nodes.empty())
    throw core::UsageError("object \"" + host_id + "\" has no body to attach a pathology to");
  if (!(size > 0.0) || !std::isfinite(size))
    throw core::UsageError("a pathology's size must be a positive length in m");
  progress.begin_stage("shaping the " + kind, 3);
  const templates::SurfaceQueries tissue(host.surface, host_id + " surface");
  core::Vec3 hang = -core::Vec3::UnitZ();
  for (const auto& mark : scenario.landmarks) {
    if (mark.id == "cervix-internal-os") hang = mark.position - point;
  }
  templates::PathologyRequest shape_request;
  shape_request.edge_length = std::clamp(0.25 * size, 0.0015, 0.003);
  core::Rng rng(seed);
  std::optional<templates::PlacedPathology> placed;
  for (int attempt = 0; attempt < 20 && !placed; ++attempt)
    placed = templates::shape_pathology_at(tissue, point, kind, size, hang, shape_request, rng);
  if (!placed) {
    throw core::InputError("no room for a " + kind + " of " + std::to_string(size * 1000.0) +
                           " mm on the wall of \"" + host_id + "\" there");
  }
  progress.step();

  const bool myoma = kind.starts_with("myoma");
  const std::string material_id = myoma ? "myoma" : "endometrium";
  PathologyParts parts;
  if (!scenario.materials.contains(material_id))
    parts.material = core::shipped_material(material_id);
  const core::Material& material =
      parts.material ? *parts.material : scenario.materials.at(material_id);
  const std::string texture = myoma && scenario.textures.contains("myoma-surface")
                                  ? std::string("myoma-surface")
                                  : host.texture;

  // The template's own steps on a copy: tets by gmsh, then the base joined to the nearest knots.
  core::Scenario copy = scenario;
  if (parts.material) copy.materials[material_id] = *parts.material;
  const std::string base = myoma ? "myoma" : kind;
  const auto taken = [&](const std::string& candidate) {
    return scenario.find_object(candidate) != nullptr ||
           std::any_of(scenario.pathologies.begin(), scenario.pathologies.end(),
                       [&](const auto& p) { return p.id == candidate; });
  };
  std::string id = base;
  for (int n = 2; taken(id); ++n)
    id = base + "-" + std::to_string(n);
  templates::add_tet_object(copy, id, kind, core::ObjectRole::Pathology, material_id, texture,
                            placed->surface, material.density, progress);
  progress.step();
  templates::attach(copy, host_id, id, placed->base, 0.75 * mean_knot_spacing(host.body));
  progress.step();

  parts.object = std::move(copy.objects.back());
  parts.object.group = host.group;
  parts.record = placed->record;
  parts.record.id = id;
  parts.record.kind = kind;
  parts.record.host_object = host_id;
  parts.record.object = id;
  parts.connection = copy.connections.back();
  return parts;
}

}  // namespace viscera::studio
