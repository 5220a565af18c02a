#include "templates/laparoscopy/laparoscopy_gyn_template.h"

#include <cmath>
#include <set>

#include "core/error.h"
#include "core/modelling/layered_body.h"
#include "core/primitives/icosphere.h"
#include "core/primitives/pipe_primitive.h"
#include "core/scenario/procedure.h"
#include "templates/template_parts.h"
#include "templates/variability/parameter_distribution.h"
#include "templates/variability/smooth_deformation.h"

namespace viscera::templates {
namespace {

/// Seed 001's table: group → objects, knots, springs.
struct TableRow {
  const char* group;
  int objects, knots, springs;
};
constexpr TableRow kTable[] = {{"uterus", 1, 339, 1328},  {"ovary", 2, 230, 864},
                               {"tube", 2, 408, 1462},    {"ligament", 2, 358, 1376},
                               {"artery", 6, 594, 2508},  {"vein", 7, 675, 2844},
                               {"intestine", 1, 147, 560}};

std::string group_of(const std::string& id) {
  for (const auto& row : kTable) {
    if (id.starts_with(row.group)) return row.group;
  }
  return id;
}

/// A pipe of `radius` through `points` whose surface has about `vertices` vertices: the axial
/// spacing is refined from the ring count until the count is met within a ring.
core::SurfaceMesh pipe_with_vertices(const std::vector<core::Vec3>& points,
                                     const std::vector<double>& radii, int ring_segments,
                                     int vertices) {
  core::PipePrimitive pipe;
  pipe.points = points;
  pipe.radii = radii;
  pipe.ring_segments = ring_segments;
  pipe.start_cap = core::PipeCap::Round;
  pipe.end_cap = core::PipeCap::Round;
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i)
    length += (points[i] - points[i - 1]).norm();
  pipe.axial_spacing = length * ring_segments / vertices;
  core::SurfaceMesh surface = core::tessellate_pipe(pipe);
  for (int iteration = 0; iteration < 4; ++iteration) {
    const double ratio = static_cast<double>(surface.vertices.size()) / vertices;
    if (std::abs(ratio - 1.0) * vertices < ring_segments) break;
    pipe.axial_spacing *= ratio;
    surface = core::tessellate_pipe(pipe);
  }
  return surface;
}

/// Adds a two-layer KisMo net of `surface` (inner copy `thickness` below it) with every node
/// closer than `hold` to one of `anchors` fixed.
void add_net(core::Scenario& scenario, const std::string& id, const std::string& name,
             const std::string& material, const core::SurfaceMesh& surface, double thickness,
             double density, const std::vector<core::Vec3>& anchors, double hold) {
  core::LayerOptions layers;
  layers.layers = 1;
  layers.thickness = thickness;
  layers.mode = core::LayerMode::Offset;
  core::SceneObject object;
  object.id = id;
  object.name = name;
  object.role = id.starts_with("artery") || id.starts_with("vein") ? core::ObjectRole::Vessel
                                                                   : core::ObjectRole::Organ;
  object.material = material;
  object.texture = "peritoneum";
  object.group = "pelvis";
  object.body_kind = core::BodyKind::MassSpring;
  object.surface = surface;
  try {
    object.body = core::mass_spring_body(core::layered_mass_spring_net(surface, layers));
  } catch (const core::Error& e) {
    throw core::InputError("object " + id + ": " + e.reason());
  }
  object.body.node_mass = core::lumped_node_masses(object.body, density);
  object.body.fixed.assign(object.body.nodes.size(), 0);
  int fixed = 0;
  for (std::size_t n = 0; n < object.body.nodes.size(); ++n) {
    for (const auto& a : anchors) {
      if ((object.body.nodes[n] - a).norm() < hold) object.body.fixed[n] = 1;
    }
    fixed += object.body.fixed[n];
  }
  if (fixed < 3) throw core::InputError("object " + id + ": fewer than 3 knots held");
  object.embedding = core::embed_leading_nodes(object.body, surface.vertices.size());
  scenario.objects.push_back(std::move(object));
}

core::Vec3 mirror(const core::Vec3& v, double side) {
  return {side * v.x(), v.y(), v.z()};
}

}  // namespace

std::string LaparoscopyGynTemplate::description() const {
  return "gynaecological laparoscopy scene of seed 001: uterus, ovaries, tubes, ligaments, "
         "arterial and venous trees and intestine as 21 two-layer KisMo nets";
}

std::vector<TemplateParameter> LaparoscopyGynTemplate::parameters() const {
  return {
      {"uterus_length", "m", "cervix to fundus", 0.05, 0.09, 0.07, false},
      {"uterus_width", "m", "between the cornua", 0.035, 0.06, 0.05, false},
      {"ovary_length", "m", "long axis of each ovary", 0.02, 0.045, 0.03, false},
      {"tube_radius", "m", "fallopian tube radius", 0.002, 0.005, 0.003, false},
      {"vessel_radius", "m", "radius of the main vessels (branches 0.7x)", 0.0015, 0.004, 0.0025,
       false},
      {"resolution", "1", "scales every object's knot count (1: seed 001's table)", 0.5, 3.0, 1.0,
       false},
      {"shape_amplitude", "m", "amplitude of the smooth random shape field", 0.0, 0.004, 0.0,
       false},
      {"stiffness", "Pa", "distance stiffness density of the organs", 2000, 80000, 15000, false},
      {"vessel_stiffness", "Pa", "distance stiffness density of vessels", 5000, 200000, 40000,
       false},
      {"density", "kg/m^3", "tissue density", 900, 1200, 1050, false},
      {"heart_rate", "1/min", "heart rate of the arteries' pulse", 40, 160, 72, false},
      {"texture_seed", "count", "seed of the peritoneum texture", 0, 1e9, 1, true},
      {"texture_size", "count", "width and height of the baked maps in pixels", 64, 2048, 256,
       true},
  };
}

std::vector<core::VariabilityRule> LaparoscopyGynTemplate::default_variability() const {
  return {truncated_normal_rule("uterus_length", 0.07, 0.006, 0.058, 0.085),
          truncated_normal_rule("uterus_width", 0.05, 0.004, 0.042, 0.058),
          uniform_rule("ovary_length", 0.025, 0.035),
          uniform_rule("shape_amplitude", 0.0, 0.002),
          truncated_normal_rule("stiffness", 15000, 3000, 8000, 25000),
          integer_range_rule("texture_seed", 0, 1000000000)};
}

core::Scenario LaparoscopyGynTemplate::build(const ParameterValues& p, std::uint64_t seed,
                                             core::Progress& progress) const {
  progress.begin_stage("laparoscopy scene", 21);
  core::Rng rng(seed);
  const double res = p.at("resolution"), density = p.at("density");
  const double L = p.at("uterus_length"), W = p.at("uterus_width");
  core::Scenario scenario;
  scenario.metadata = {"laparoscopy-gyn", "Gynaecological laparoscopy scene (seed 001 §3.3).",
                       "viscera template laparoscopy-gyn"};
  scenario.procedure = procedure();
  add_material(scenario, "organ", "Pelvic organ", density, p.at("stiffness"),
               "soft organ wall, order of seed 001's measured curves");
  add_material(scenario, "vessel", "Vessel wall", density, p.at("vessel_stiffness"),
               "elastic vessel wall, stiffer than the organs");
  add_texture(scenario, "peritoneum", "peritoneum",
              static_cast<std::uint64_t>(p.at("texture_seed")),
              static_cast<int>(p.at("texture_size")));
  const auto knots = [&](int table_knots) {
    return std::max(24, static_cast<int>(std::lround(res * table_knots / 2.0)));
  };

  // Uterus: an ellipsoid (cervix at z = 0, fundus at z = L) with a smooth random shape field.
  core::BoundingBox box;
  box.add({-W, -W, 0.0});
  box.add({W, W, L});
  const SmoothDeformation field =
      SmoothDeformation::random(rng, box, 6, p.at("shape_amplitude"), 0.02, 0.5);
  {
    int level = 0;
    while (10 * (1 << (2 * (level + 1))) + 2 <= knots(339) + 10)
      ++level;
    core::SurfaceMesh u = core::make_icosphere(1.0, level);
    for (auto& v : u.vertices)
      v = field.apply(core::Vec3(0.5 * W * v.x(), 0.35 * W * v.y(), 0.5 * L * (v.z() + 1.0)));
    core::compute_vertex_normals(u);
    add_net(scenario, "uterus", "Uterus", "organ", u, 0.1 * W, density,
            {core::Vec3(0.0, 0.0, 0.0), core::Vec3(0.5 * W, 0.0, 0.7 * L),
             core::Vec3(-0.5 * W, 0.0, 0.7 * L)},
            0.25 * L);
    progress.step();
  }
  for (const double side : {-1.0, 1.0}) {
    const std::string s = side < 0 ? "right" : "left";
    const double ol = p.at("ovary_length");
    const core::Vec3 ovary_a = mirror({0.5 * W + 0.022, 0.012, 0.45 * L}, side);
    const core::Vec3 ovary_b = ovary_a + mirror({0.6 * ol, 0.0, -0.8 * ol}, side);
    add_net(scenario, "ovary-" + s, "Ovary (" + s + ")", "organ",
            pipe_with_vertices({ovary_a, ovary_b}, {0.28 * ol, 0.28 * ol}, 8, knots(115)),
            0.08 * ol, density, {ovary_a, ovary_b}, 0.4 * ol);
    progress.step();
    const double tr = p.at("tube_radius");
    const core::Vec3 cornu = mirror({0.5 * W + tr + 0.003, 0.0, 0.85 * L}, side);
    add_net(
        scenario, "tube-" + s, "Fallopian tube (" + s + ")", "organ",
        pipe_with_vertices({cornu, cornu + mirror({0.03, 0.0, 0.01}, side),
                            cornu + mirror({0.055, -0.012, -0.01}, side),
                            cornu + mirror({0.06, -0.02, -0.035}, side)},
                           {tr, tr, 1.2 * tr, 1.6 * tr}, 8, knots(204)),
        0.4 * tr, density,
        // Held at every pipe point (the mesosalpinx carries the tube along its length),
        // but only 1.5 radii around each, so the isthmus stays free for 2 cm: room to
        // grasp, coagulate, clip twice and cut.
        {cornu, cornu + mirror({0.03, 0.0, 0.01}, side),
         cornu + mirror({0.055, -0.012, -0.01}, side), cornu + mirror({0.06, -0.02, -0.035}, side)},
        1.5 * tr);
    // The isthmus, where a tube is occluded: on the front (−y, where the laparoscope looks
    // from) of the middle of its first, narrow segment.
    scenario.landmarks.push_back(
        {"fallopian-tube-" + s, "Isthmus of the fallopian tube (" + s + ")", "tube-" + s,
         cornu + mirror({0.015, 0.0, 0.005}, side) - tr * core::Vec3::UnitY(),
         -core::Vec3::UnitY()});
    progress.step();
    const core::Vec3 lig = mirror({0.5 * W + 0.004, -0.012, 0.65 * L}, side);
    const core::Vec3 lig_end = lig + mirror({0.06, -0.05, -0.02}, side);
    add_net(scenario, "ligament-" + s, "Round ligament (" + s + ")", "organ",
            pipe_with_vertices({lig, lig + mirror({0.03, -0.025, -0.005}, side), lig_end},
                               {0.003, 0.0028, 0.0025}, 8, knots(179)),
            0.0012, density, {lig, lig + mirror({0.03, -0.025, -0.005}, side), lig_end}, 0.009);
    progress.step();
  }
  // Vessels: per side the uterine vessel from the pelvic wall to the uterus, its ascending
  // branch beside the uterus and the ovarian vessel from above; the venous tree adds the
  // presacral vein. Arteries lie behind (y > 0) the veins.
  const double vr = p.at("vessel_radius");
  const auto add_vessel = [&](const std::string& id, const std::string& name,
                              std::vector<core::Vec3> points, double radius, int table_knots) {
    add_net(scenario, id, name, "vessel",
            pipe_with_vertices(points, std::vector<double>(points.size(), radius), 6,
                               knots(table_knots)),
            0.35 * radius, density, points, 2.5 * radius);
    if (id.starts_with("artery")) {
      // Seed 001 §5.1.1: the artery pulses, a wave from its first point along its axis.
      core::VesselTree tree;
      tree.id = id + "-tree";
      tree.host_object = id;
      tree.kind = "arterial";
      for (std::size_t k = 0; k + 1 < points.size(); ++k)
        tree.segments.push_back(
            {static_cast<int>(k), static_cast<int>(k) - 1, points[k], points[k + 1], radius, 0.0});
      scenario.vessel_trees.push_back(tree);
      core::PulseSpec pulse;
      pulse.vessel_tree = tree.id;
      pulse.heart_rate = p.at("heart_rate");
      pulse.pulse_velocity = 6.0;  // m/s, the pulse wave velocity of pelvic arteries
      pulse.wall_force = 0.001;    // N per wall knot as the front passes: a visible throb
      scenario.active_deformations.push_back({id + "-pulse", id, pulse});
    }
    progress.step();
  };
  for (const bool artery : {true, false}) {
    const std::string kind = artery ? "artery" : "vein";
    const double depth = artery ? 0.03 : 0.042;
    const double r = artery ? vr : 1.2 * vr;
    const int per_object = artery ? 99 : 96;
    for (const double side : {-1.0, 1.0}) {
      const std::string s = side < 0 ? "right" : "left";
      const core::Vec3 wall = mirror({0.5 * W + 0.05, depth, 0.1 * L}, side);
      const core::Vec3 near = mirror({0.5 * W + 0.008, depth, 0.15 * L}, side);
      add_vessel(kind + "-uterine-" + s, "Uterine " + kind + " (" + s + ")",
                 {wall, 0.5 * (wall + near) + core::Vec3(0, 0, -0.005), near}, r, per_object);
      add_vessel(kind + "-ascending-" + s, "Ascending uterine " + kind + " (" + s + ")",
                 {near + core::Vec3(0, 0, 0.006), near + mirror({0.002, 0, 0.35 * L}, side),
                  near + mirror({0.0, 0, 0.7 * L}, side)},
                 0.7 * r, per_object);
      add_vessel(kind + "-ovarian-" + s, "Ovarian " + kind + " (" + s + ")",
                 {mirror({0.5 * W + 0.045, depth, 1.4 * L}, side),
                  mirror({0.5 * W + 0.035, depth, 1.0 * L}, side),
                  mirror({0.5 * W + 0.03, depth, 0.75 * L}, side)},
                 0.7 * r, per_object);
    }
    if (!artery) {
      add_vessel("vein-presacral", "Presacral vein",
                 {core::Vec3(-0.02, 0.055, -0.01), core::Vec3(0.0, 0.055, 0.02),
                  core::Vec3(0.02, 0.055, 0.05)},
                 r, 99);
    }
  }
  // Intestine: a sigmoid loop behind and above the uterus.
  add_net(
      scenario, "intestine", "Sigmoid colon", "organ",
      pipe_with_vertices({core::Vec3(-0.04, 0.07, 0.04), core::Vec3(-0.01, 0.075, 0.08),
                          core::Vec3(0.03, 0.07, 0.1)},
                         {0.012, 0.013, 0.012}, 10, knots(147)),
      0.003, density,
      {core::Vec3(-0.04, 0.07, 0.04), core::Vec3(-0.01, 0.075, 0.08), core::Vec3(0.03, 0.07, 0.1)},
      0.02);
  progress.step();

  // Seed 001 §5.2: the sigmoid's periodic motility, a slow wave along the colon.
  core::MotilitySpec peristalsis;
  peristalsis.amplitude_mean = 0.002;
  peristalsis.wave_speed = 0.01;
  peristalsis.wave_direction = core::Vec3(0.7, 0.05, 0.7).normalized();
  peristalsis.frequency = 0.1;
  peristalsis.frequency_disturbance = 0.02;
  scenario.active_deformations.push_back({"intestine-motility", "intestine", peristalsis});

  scenario.fluid.enabled = false;
  scenario.session.contact_stiffness = 0.0;  // seed 001: organs are kept apart by their holds
  // Seed 001 §3.1: locate both tubes (detected), grasp, clip and cut (reported unavailable).
  core::apply_procedure(scenario.session,
                        core::procedure_definition("laparoscopic-tubal-sterilisation"));
  return scenario;
}

nlohmann::json LaparoscopyGynTemplate::reference_counts() const {
  return laparoscopy_gyn_counts(build(resolve_parameters(*this, {}), 1, core::Progress::none()));
}

nlohmann::json laparoscopy_gyn_counts(const core::Scenario& scenario) {
  std::map<std::string, std::array<std::size_t, 3>> ours;
  for (const auto& o : scenario.objects) {
    std::set<std::pair<int, int>> edges;
    for (const auto& t : o.body.tets) {
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
          edges.insert({std::min(t[a], t[b]), std::max(t[a], t[b])});
    }
    auto& row = ours[group_of(o.id)];
    row[0] += 1;
    row[1] += o.body.nodes.size();
    row[2] += edges.size();
  }
  nlohmann::json out = nlohmann::json::object();
  std::array<std::size_t, 3> total{};
  std::array<int, 3> seed_total{};
  for (const auto& row : kTable) {
    const auto& c = ours[row.group];
    out[row.group] = {{"objects", c[0]},         {"knots", c[1]},
                      {"springs", c[2]},         {"seed_objects", row.objects},
                      {"seed_knots", row.knots}, {"seed_springs", row.springs}};
    for (int i = 0; i < 3; ++i)
      total[static_cast<std::size_t>(i)] += c[static_cast<std::size_t>(i)];
    seed_total[0] += row.objects, seed_total[1] += row.knots, seed_total[2] += row.springs;
  }
  out["total"] = {{"objects", total[0]},         {"knots", total[1]},
                  {"springs", total[2]},         {"seed_objects", seed_total[0]},
                  {"seed_knots", seed_total[1]}, {"seed_springs", seed_total[2]}};
  return out;
}

}  // namespace viscera::templates
