#include "studio/document/organ_authoring.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/lsystem/lsystem.h"
#include "core/materials/shipped_materials.h"
#include "core/mesh/tet_quality.h"
#include "core/random.h"
#include "templates/geometry/surface_queries.h"
#include "templates/hysteroscopy/uterine_pathologies.h"
#include "templates/template_parts.h"
#include "templates/validation/patient_validation.h"
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

/// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection §5.1.5).
core::Vec3 closest_on_triangle(const core::Vec3& p, const core::Vec3& a, const core::Vec3& b,
                               const core::Vec3& c) {
  const core::Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const core::Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const core::Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace

std::string wall_side_of(const std::string& kind) {
  if (kind == "myoma-subserosal") return "serosa";
  if (kind == "myoma-intramural") return "wall";
  if (kind == "polyp" || kind == "myoma-submucosal" || kind == "myoma-pedunculated")
    return "cavity";
  throw core::UsageError(
      "a pathology placed on a wall is polyp, myoma-submucosal, myoma-pedunculated, "
      "myoma-intramural or myoma-subserosal, not \"" +
      kind + "\"");
}

std::optional<core::Vec3> snap_to_wall_side(const core::SurfaceMesh& surface,
                                            const core::Vec3& point, const std::string& side) {
  const auto region = surface.vertex_attributes.find("cavity");
  if (region == surface.vertex_attributes.end() || region->second.size() != surface.vertices.size())
    return std::nullopt;
  // Cavity wall: vertices marked 1 (2 is the cervical canal); serosa: the outside, 0.
  const double wanted = side == "cavity" ? 1.0 : 0.0;
  std::optional<core::Vec3> best;
  double best_distance = 0.0;
  for (const auto& tri : surface.triangles) {
    if (region->second[static_cast<std::size_t>(tri[0])] != wanted ||
        region->second[static_cast<std::size_t>(tri[1])] != wanted ||
        region->second[static_cast<std::size_t>(tri[2])] != wanted)
      continue;
    const core::Vec3 q = closest_on_triangle(point, surface.vertices[tri[0]],
                                             surface.vertices[tri[1]], surface.vertices[tri[2]]);
    const double distance = (q - point).squaredNorm();
    if (!best || distance < best_distance) {
      best = q;
      best_distance = distance;
    }
  }
  return best;
}

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
  // A baked texture cuts the surface at its seams; the domain needs it closed (as validation).
  const templates::SurfaceMeshDomain domain(textures::welded_surface(organ.surface),
                                            object_id + " surface");
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
  const std::string side = wall_side_of(kind);
  progress.begin_stage("shaping the " + kind, 3);
  // A baked texture cuts the surface at its seams: the queries need the closed surface, as the
  // variant validation uses (textures::welded_surface keeps the "cavity" marks).
  const core::SurfaceMesh wall = textures::welded_surface(host.surface);
  const templates::SurfaceQueries tissue(wall, host_id + " surface");
  // Intracavitary lesions sit on the cavity side of the wall, subserosal ones on the outside,
  // wherever on the organ the click landed (a hollow organ marks its cavity wall); an
  // intramural one lies in the wall beneath the click, whichever side that is.
  const bool in_wall = side == "wall";
  const core::Vec3 site = in_wall ? point : snap_to_wall_side(wall, point, side).value_or(point);
  // A subserosal myoma is shaped as a sessile one: bulging out of the wall along its normal.
  const std::string shape_kind = kind == "myoma-subserosal" ? "myoma-submucosal" : kind;
  core::Vec3 hang = -core::Vec3::UnitZ();
  for (const auto& mark : scenario.landmarks) {
    if (mark.id == "cervix-internal-os") hang = mark.position - site;
  }
  templates::PathologyRequest shape_request;
  shape_request.edge_length = std::clamp(0.25 * size, 0.0015, 0.003);
  core::Rng rng(seed);
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
  const std::string base = myoma ? "myoma" : kind;
  const auto taken = [&](const std::string& candidate) {
    return scenario.find_object(candidate) != nullptr ||
           std::any_of(scenario.pathologies.begin(), scenario.pathologies.end(),
                       [&](const auto& p) { return p.id == candidate; });
  };
  std::string id = base;
  for (int n = 2; taken(id); ++n)
    id = base + "-" + std::to_string(n);

  // The template's own steps on a copy: the shape, tets by gmsh, then the base joined to the
  // nearest knots. A draw that does not fit, or whose tets gmsh leaves with a sliver the
  // validation refuses, is drawn again, as the variant generator does. An intramural myoma is
  // drawn once (its sphere is not random) and its host re-meshed around it.
  const templates::ValidationBounds bounds;
  const auto acceptable = [&](const core::TetMesh& body) {
    const core::TetQualityReport quality = core::tet_quality(body);
    return quality.inverted == 0 && quality.min_dihedral_degrees >= bounds.min_dihedral_degrees;
  };
  std::optional<templates::PlacedPathology> placed;
  core::Scenario copy;
  for (int attempt = 0; attempt < (in_wall ? 1 : 20) && !placed; ++attempt) {
    placed =
        templates::shape_pathology_at(tissue, site, shape_kind, size, hang, shape_request, rng);
    if (!placed) continue;
    copy = scenario;
    if (parts.material) copy.materials[material_id] = *parts.material;
    templates::add_tet_object(copy, id, kind, core::ObjectRole::Pathology, material_id, texture,
                              placed->surface, material.density, core::Progress::none());
    if (!acceptable(copy.objects.back().body)) placed.reset();
  }
  if (!placed) {
    throw core::InputError("no room for a " + kind + " of " + std::to_string(size * 1000.0) +
                           (in_wall ? " mm in the wall of \"" : " mm on the wall of \"") + host_id +
                           "\" there");
  }
  progress.step();
  if (in_wall) {
    parts.host = remesh_around_holes(scenario, host_id, {placed->surface}, progress);
    progress.begin_stage("joining the " + kind + " to its host", 2);
    if (!acceptable(parts.host->object.body)) {
      throw core::InputError("the wall of \"" + host_id + "\" re-meshed around a " +
                             std::to_string(size * 1000.0) +
                             " mm myoma there has a sliver tet: place it elsewhere");
    }
    for (auto& object : copy.objects) {
      if (object.id == host_id) object = parts.host->object;
    }
    for (auto& connection : copy.connections) {
      for (const auto& moved : parts.host->connections) {
        if (moved.id == connection.id) connection = moved;
      }
    }
  }
  progress.step();
  // The myoma's sphere lines its hole node for node; a seated base meets the nearest knots.
  templates::attach(copy, host_id, id, placed->base,
                    in_wall ? 1e-6 : 0.75 * mean_knot_spacing(host.body));
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
