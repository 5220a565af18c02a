#include "templates/hysteroscopy/hysteroscopy_template.h"

#include <algorithm>
#include <cmath>

#include "core/meshing/tet_mesher.h"
#include "core/modelling/layered_body.h"
#include "core/modelling/object_connectivity.h"
#include "core/scenario/procedure.h"
#include "templates/hysteroscopy/uterine_pathologies.h"
#include "templates/hysteroscopy/uterus_shape.h"
#include "templates/template_parts.h"
#include "templates/variability/parameter_distribution.h"
#include "templates/vessels/cco_vessel_generator.h"

namespace viscera::templates {

namespace {

/// What each variant is called, says of itself and embeds as its procedure.
struct VariantFacts {
  const char* name;
  const char* description;
  const char* procedure;
};

VariantFacts facts_of(HysteroscopyVariant variant) {
  switch (variant) {
    case HysteroscopyVariant::polypectomy:
      return {"hysteroscopy-polypectomy",
              "the hysteroscopy patient with at least one endometrial polyp, a resectoscope and "
              "the hysteroscopic polypectomy procedure",
              "hysteroscopic-polypectomy"};
    case HysteroscopyVariant::myomectomy:
      return {"hysteroscopy-myomectomy",
              "the hysteroscopy patient with one or two sessile submucosal myomas, a resectoscope "
              "and the hysteroscopic myomectomy procedure (shaving)",
              "hysteroscopic-myomectomy"};
    case HysteroscopyVariant::diagnostic:
      break;
  }
  return {"hysteroscopy",
          "uterus with cavity, cervical canal, tubal orifices, endometrium and myometrium, fixed "
          "cervix, arterial tree and random myomas, polyps and adhesions",
          "diagnostic-hysteroscopy"};
}

}  // namespace

std::string HysteroscopyTemplate::name() const {
  return facts_of(variant_).name;
}

std::string HysteroscopyTemplate::description() const {
  return facts_of(variant_).description;
}

std::vector<TemplateParameter> HysteroscopyTemplate::parameters() const {
  const bool polypectomy = variant_ == HysteroscopyVariant::polypectomy;
  const bool myomectomy = variant_ == HysteroscopyVariant::myomectomy;
  return {
      {"length", "m", "external os to the top of the fundus", 0.06, 0.09, 0.075, false},
      {"width", "m", "largest outer width of the uterus", 0.04, 0.06, 0.05, false},
      {"thickness", "m", "largest antero-posterior thickness", 0.028, 0.045, 0.035, false},
      {"cervix_length", "m", "cervical canal, external to internal os", 0.018, 0.032, 0.025, false},
      {"canal_radius", "m", "radius of the distended cervical canal", 0.0018, 0.0035, 0.0025,
       false},
      {"cavity_length", "m", "internal os to the top of the cavity", 0.026, 0.042, 0.034, false},
      {"cavity_width", "m", "distance between the cornua", 0.022, 0.036, 0.028, false},
      {"cavity_depth", "m", "antero-posterior opening of the distended cavity", 0.008, 0.016, 0.012,
       false},
      {"flexion", "rad", "anteflexion of the body (negative: retroflexion)", -0.4, 0.8, 0.3, false},
      {"shape_amplitude", "m", "amplitude of the smooth random shape field", 0.0, 0.004, 0.0015,
       false},
      {"edge_length", "m",
       "outer triangle edge (cavity 0.7x, canal 0.5x); sets the body resolution", 0.003, 0.01,
       0.0055, false},
      {"endometrium_thickness", "m", "endometrial layer of the wall", 0.002, 0.008, 0.004, false},
      {"fixed_cervix_fraction", "1", "fixed nodes: lower fraction of the cervix length", 0.1, 1.0,
       0.5, false},
      {"submucosal_myomas", "count", "sessile myomas bulging into the cavity",
       myomectomy ? 1.0 : 0.0, 3, 1, true},
      // The myomectomy patient has sessile myomas only, so "myoma-1" is the one to shave.
      {"intramural_myomas", "count", "myomas inside the wall", 0, myomectomy ? 0.0 : 2.0, 0, true},
      {"pedunculated_myomas", "count", "myomas on a stalk", 0, myomectomy ? 0.0 : 2.0, 0, true},
      {"polyps", "count", "endometrial polyps", polypectomy ? 1.0 : 0.0, 4, myomectomy ? 0.0 : 1.0,
       true},
      {"adhesions", "count", "bands between opposite walls (synechiae)", 0, 3, 0, true},
      {"myoma_diameter", "m", "mean myoma diameter (each drawn within 25 %)", 0.004, 0.014, 0.008,
       false},
      {"polyp_length", "m", "mean polyp length", 0.003, 0.014, 0.007, false},
      {"adhesion_radius", "m", "mean adhesion band radius", 0.0008, 0.002, 0.0012, false},
      {"myometrium_stiffness", "Pa", "Teschner distance stiffness density of the myometrium", 5000,
       80000, 20000, false},
      {"endometrium_stiffness", "Pa", "distance stiffness density of the endometrium", 2000, 40000,
       8000, false},
      {"myoma_stiffness", "Pa", "distance stiffness density of myomas (stiffer than the wall)",
       20000, 200000, 40000, false},
      {"density", "kg/m^3", "tissue density", 900, 1200, 1050, false},
      {"vessel_terminals", "count", "terminal segments of the CCO arterial tree (0: none)", 0, 400,
       60, true},
      {"vessel_seed", "count", "seed of the arterial tree", 0, 1e9, 1, true},
      {"pathology_artery_radius", "m",
       "radius of the artery feeding each polyp and cavity myoma up its axis (0: none); a cut "
       "across it bleeds",
       0.0, 0.0006, 0.0, false},
      {"texture_seed", "count", "seed of the tissue textures", 0, 1e9, 1, true},
      {"texture_size", "count", "width and height of the baked maps in pixels", 64, 2048, 256,
       true},
  };
}

namespace {

/// The myomectomy patient's variability: the diagnostic patient's shape, one or two sessile
/// myomas of 6–10 mm (FIGO type 1–2 lesions a 26 Fr loop shaves in a few layers), no polyps,
/// no intramural or pedunculated myomas (so "myoma-1" is the first sessile one).
std::vector<core::VariabilityRule> myomectomy_variability(
    std::vector<core::VariabilityRule> rules) {
  std::erase_if(rules, [](const core::VariabilityRule& r) {
    return r.parameter.find("myoma") != std::string::npos || r.parameter == "polyps";
  });
  rules.push_back(integer_range_rule("submucosal_myomas", 1, 2));
  rules.push_back(integer_range_rule("intramural_myomas", 0, 0));
  rules.push_back(integer_range_rule("pedunculated_myomas", 0, 0));
  rules.push_back(integer_range_rule("polyps", 0, 0));
  rules.push_back(uniform_rule("myoma_diameter", 0.006, 0.01));
  rules.push_back(truncated_normal_rule("myoma_stiffness", 40000, 8000, 25000, 70000));
  return rules;
}

}  // namespace

std::vector<core::VariabilityRule> HysteroscopyTemplate::default_variability() const {
  std::vector<core::VariabilityRule> rules{
      truncated_normal_rule("length", 0.075, 0.006, 0.065, 0.09),
      truncated_normal_rule("width", 0.05, 0.004, 0.043, 0.058),
      truncated_normal_rule("thickness", 0.035, 0.003, 0.03, 0.042),
      uniform_rule("cervix_length", 0.022, 0.028),
      uniform_rule("cavity_length", 0.03, 0.038),
      uniform_rule("cavity_width", 0.024, 0.032),
      uniform_rule("cavity_depth", 0.01, 0.015),
      uniform_rule("flexion", -0.2, 0.6),
      uniform_rule("shape_amplitude", 0.0005, 0.003),
      integer_range_rule("submucosal_myomas", 0, 2),
      integer_range_rule("intramural_myomas", 0, 1),
      choice_rule("pedunculated_myomas", {0, 1}, {3, 1}),
      integer_range_rule("polyps", variant_ == HysteroscopyVariant::polypectomy ? 1 : 0, 3),
      choice_rule("adhesions", {0, 1, 2}, {6, 2, 1}),
      uniform_rule("myoma_diameter", 0.005, 0.012),
      uniform_rule("polyp_length", 0.004, 0.011),
      truncated_normal_rule("myometrium_stiffness", 20000, 4000, 10000, 35000),
      truncated_normal_rule("endometrium_stiffness", 8000, 1600, 4000, 14000),
      truncated_normal_rule("myoma_stiffness", 40000, 8000, 25000, 70000),
      integer_range_rule("vessel_seed", 0, 1000000000),
      integer_range_rule("texture_seed", 0, 1000000000),
  };
  if (variant_ == HysteroscopyVariant::myomectomy) return myomectomy_variability(std::move(rules));
  return rules;
}

namespace {

UterusDimensions dimensions_of(const ParameterValues& p) {
  UterusDimensions d;
  d.length = p.at("length");
  d.width = p.at("width");
  d.thickness = p.at("thickness");
  d.cervix_length = p.at("cervix_length");
  d.canal_radius = p.at("canal_radius");
  d.cavity_length = p.at("cavity_length");
  d.cavity_width = p.at("cavity_width");
  d.cavity_depth = p.at("cavity_depth");
  d.flexion = p.at("flexion");
  d.edge_length = p.at("edge_length");
  return d;
}

/// Endometrium (label 1) where a tet's centroid lies within `thickness` of the cavity wall,
/// myometrium (label 2) elsewhere.
std::vector<int> wall_layers(const core::TetMesh& body, const UterusShape& shape,
                             const SurfaceQueries& tissue, double thickness) {
  std::vector<int> labels(body.tets.size(), 2);
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    core::Vec3 c = core::Vec3::Zero();
    for (const int n : body.tets[t])
      c += body.nodes[static_cast<std::size_t>(n)];
    const SurfacePoint near = tissue.closest(c / 4.0);
    const auto& tri = shape.surface.triangles[static_cast<std::size_t>(near.triangle)];
    if (near.distance < thickness && shape.cavity[static_cast<std::size_t>(tri[0])] == 1)
      labels[t] = 1;
  }
  return labels;
}

}  // namespace

core::Scenario HysteroscopyTemplate::build(const ParameterValues& p, std::uint64_t seed,
                                           core::Progress& progress) const {
  progress.begin_stage("hysteroscopy patient", 5);
  core::Rng rng(seed);
  const UterusDimensions dims = dimensions_of(p);
  check_uterus_dimensions(dims);
  core::BoundingBox box;
  box.add({-0.5 * dims.width, -0.5 * dims.thickness, 0.0});
  box.add({0.5 * dims.width, 0.5 * dims.thickness, dims.length});
  const SmoothDeformation field =
      SmoothDeformation::random(rng, box, 8, p.at("shape_amplitude"), 0.02, 0.5);
  UterusShape shape = make_uterus(dims, field);
  const SurfaceQueries tissue(shape.surface, "uterus surface");
  progress.step();

  PathologyRequest request;
  request.submucosal_myomas = static_cast<int>(p.at("submucosal_myomas"));
  request.intramural_myomas = static_cast<int>(p.at("intramural_myomas"));
  request.pedunculated_myomas = static_cast<int>(p.at("pedunculated_myomas"));
  request.polyps = static_cast<int>(p.at("polyps"));
  request.adhesions = static_cast<int>(p.at("adhesions"));
  request.myoma_diameter = p.at("myoma_diameter");
  request.polyp_length = p.at("polyp_length");
  request.adhesion_radius = p.at("adhesion_radius");
  request.sessile_on_corpus_faces = variant_ == HysteroscopyVariant::myomectomy;
  request.edge_length = std::clamp(0.45 * dims.edge_length, 0.002, 0.003);
  const std::vector<PlacedPathology> pathologies = place_pathologies(shape, tissue, request, rng);
  progress.step();

  core::Scenario scenario;
  scenario.metadata = {
      "hysteroscopy", "A uterus for diagnostic and operative hysteroscopy with random pathologies.",
      "viscera template hysteroscopy"};
  scenario.procedure = procedure();
  const double density = p.at("density");
  add_material(
      scenario, "myometrium", "Myometrium", density, p.at("myometrium_stiffness"),
      "smooth muscle wall; order of in-vivo aspiration data (Nava et al. 2004, seed 000 §2.1)");
  add_material(scenario, "endometrium", "Endometrium", density, p.at("endometrium_stiffness"),
               "soft mucosal layer, about 0.4 times the myometrium");
  add_material(scenario, "myoma", "Leiomyoma", density, p.at("myoma_stiffness"),
               "fibrous tumour, about 3 times the myometrium");
  add_material(scenario, "adhesion", "Fibrous adhesion", density, p.at("myometrium_stiffness"),
               "thin collagen band, as stiff as the wall");
  add_texture(scenario, "endometrium", "endometrium",
              static_cast<std::uint64_t>(p.at("texture_seed")),
              static_cast<int>(p.at("texture_size")));
  add_texture(scenario, "myoma-surface", "myoma-surface",
              static_cast<std::uint64_t>(p.at("texture_seed")) + 1,
              static_cast<int>(p.at("texture_size")));

  // The wall: gmsh fills the uterus (intramural myomas are holes in it), sized by the surface.
  std::vector<core::SurfaceMesh> holes;
  for (const auto& pathology : pathologies) {
    if (pathology.in_wall) holes.push_back(pathology.surface);
  }
  core::SceneObject uterus;
  uterus.id = "uterus";
  uterus.name = "Uterus";
  uterus.role = core::ObjectRole::Organ;
  uterus.material = "myometrium";
  uterus.layer_materials = {{1, "endometrium"}, {2, "myometrium"}};
  uterus.texture = "endometrium";
  uterus.body_kind = core::BodyKind::TetMesh;
  uterus.body = core::mesh_region_between(shape.surface, holes, {}, progress);
  uterus.body.tet_labels = wall_layers(uterus.body, shape, tissue, p.at("endometrium_thickness"));
  uterus.body.node_mass = core::lumped_node_masses(uterus.body, density);
  // Seed 000 §2.1: "the vertices near the cervix are fixed".
  const double fixed_below = p.at("fixed_cervix_fraction") * dims.cervix_length;
  uterus.body.fixed.assign(uterus.body.nodes.size(), 0);
  for (std::size_t n = 0; n < uterus.body.nodes.size(); ++n)
    uterus.body.fixed[n] = uterus.body.nodes[n].z() <= fixed_below;
  uterus.surface = shape.surface;
  std::vector<double> region(shape.cavity.begin(), shape.cavity.end());
  uterus.surface.vertex_attributes["cavity"] = region;
  uterus.embedding = core::embed_leading_nodes(uterus.body, uterus.surface.vertices.size());
  scenario.objects.push_back(std::move(uterus));
  progress.step();

  for (const auto& pathology : pathologies) {
    const bool band = pathology.record.kind == "adhesion";
    const bool myoma = pathology.record.kind.starts_with("myoma");
    add_tet_object(scenario, pathology.record.id, pathology.record.kind,
                   core::ObjectRole::Pathology,
                   band ? "adhesion" : (myoma ? "myoma" : "endometrium"),
                   myoma ? "myoma-surface" : "endometrium", pathology.surface, density, progress);
    scenario.pathologies.push_back(pathology.record);
    // Attached at the nearest knots: the hole's nodes for an intramural myoma, the seated base
    // otherwise.
    attach(scenario, "uterus", pathology.record.id, pathology.base,
           pathology.in_wall ? 1e-6 : 0.6 * dims.edge_length);
  }
  assign_organ_group(scenario, "uterus", [&] {
    std::vector<std::string> ids;
    for (const auto& o : scenario.objects)
      ids.push_back(o.id);
    return ids;
  }());
  progress.step();

  const int terminals = static_cast<int>(p.at("vessel_terminals"));
  if (terminals > 0) {
    const SurfaceMeshDomain domain(shape.surface, "uterus wall");
    CcoOptions cco;
    cco.terminals = terminals;
    cco.seed = static_cast<std::uint64_t>(p.at("vessel_seed"));
    cco.tree_id = "uterine-artery";
    cco.host_object = "uterus";
    scenario.vessel_trees.push_back(grow_cco_tree(domain, cco));
  }
  // The tubal orifices lie at the bottom of their funnels; on the coarse mesh the facets there
  // sit in front of the smooth funnel's apex, so the landmarks move onto the mesh (a camera
  // centring one sees it, not the facet in front of it).
  scenario.landmarks = shape.landmarks;
  // Each pathology in the cavity is a landmark at its apex, with the normal from base to apex,
  // and one ("ID-base") at the centre of its base on the wall, with the wall's normal there (a
  // place offset along it in the base's frame lies at a height above the wall, whichever way
  // a stalk leans): scripts and centring tasks find them, and script places take offsets in
  // their frames (resolve_script_landmarks).
  for (const auto& pathology : pathologies) {
    if (pathology.in_wall || pathology.record.kind == "adhesion") continue;
    const auto& v = pathology.surface.vertices;
    core::Vec3 base = core::Vec3::Zero();
    for (const int i : pathology.base)
      base += v[static_cast<std::size_t>(i)];
    base /= static_cast<double>(std::max<std::size_t>(pathology.base.size(), 1));
    const core::Vec3 apex =
        *std::max_element(v.begin(), v.end(), [&](const auto& a, const auto& b) {
          return (a - base).squaredNorm() < (b - base).squaredNorm();
        });
    const core::Vec3 axis = (apex - base).normalized();
    scenario.landmarks.push_back(
        {pathology.record.id, "apex of " + pathology.record.id, pathology.record.id, apex, axis});
    const core::Vec3 wall =
        pathology.wall_normal.norm() > 0.0 ? core::Vec3(pathology.wall_normal.normalized()) : axis;
    scenario.landmarks.push_back({pathology.record.id + "-base", "base of " + pathology.record.id,
                                  pathology.record.id, base, wall});
    // A polyp's vascular stalk, a myoma's feeding vessel: one artery hosted by the pathology
    // from the centre of its base to nine tenths of the way to its apex.
    if (const double radius = p.at("pathology_artery_radius"); radius > 0.0) {
      core::VesselTree artery;
      artery.id = pathology.record.id + "-artery";
      artery.host_object = pathology.record.id;
      artery.segments.push_back({0, -1, base, base + 0.9 * (apex - base), radius, 0.0});
      scenario.vessel_trees.push_back(std::move(artery));
    }
  }
  for (auto& mark : scenario.landmarks) {
    if (mark.id.starts_with("tubal-orifice"))
      mark.position = tissue.closest(mark.position).position;
  }

  scenario.fluid.enabled = true;
  // The uterus rests in the pelvis, held all round; the cavity deforms under distension
  // pressure and the tools, not its own weight (seed 000 §2.1 loads the wall by pressure only).
  scenario.session.gravity = core::Vec3::Zero();
  // Pathologies are attached to the wall (their bases, which overlap the wall at rest, are
  // not contacts) and collide with it and each other when pushed; the tool touches every body
  // through the instrument proxy.
  scenario.session.contact_stiffness = 500.0;
  // Seed 000 §11: the diagnostic procedure, its tasks referring to the shape's landmarks (the
  // internal and external os, both tubal orifices) and the cavity region of the surface.
  core::apply_procedure(scenario.session, core::procedure_definition(facts_of(variant_).procedure));
  scenario.session.metrics = {"path_length", "economy_of_movement", "wall_contacts", "max_force",
                              "cavity_seen"};
  progress.step();
  return scenario;
}

}  // namespace viscera::templates
