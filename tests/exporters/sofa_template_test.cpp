// `viscera export --format sofa` of every template, run as a user runs it (into a folder that
// does not exist yet), read back with the SOFA semantics of sofa_scene_reader.h and checked
// against what Viscera simulates: per-edge spring constants, Rayleigh damping, CG settings that
// converge, the collision pipeline when there is contact, attachments that are not also holds,
// plugins by pluginName; the urethra lattice and cell-agent tissue are refused in one sentence.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "core/package/scenario_package.h"
#include "exporters/sofa_material.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/exporters/sofa_scene_reader.h"
#include "tests/exporters/sofa_template_cases.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using testing::material_of_tet;
using testing::plugin_of;
using testing::SofaElement;
using testing::SofaSceneReader;
using testing::template_package;
using testing::TemplateCase;
using testing::viscera_edges;

const TemplateCase kCases[] = {
    {"ball", "ball", "", nullptr},
    {"ball_on_floor", "ball", " --set floor=1", nullptr},
    {"hysteroscopy", "hysteroscopy", "", nullptr},
    {"laparoscopy_gyn", "laparoscopy-gyn", "", nullptr},
};
const TemplateCase kRefused[] = {
    {"urethra", "urethra", "", "urethra"},
    {"agent_tissue", "agent-tissue", "", "tissue"},
};

class SofaTemplateExport : public ::testing::TestWithParam<TemplateCase> {
 protected:
  void SetUp() override {
    const TemplateCase& c = GetParam();
    package_ = template_package(c);
    dir_ = testing::scratch_dir();
    scene_ = dir_ / "not-yet" / "made" / (std::string(c.label) + ".scn");
    result_ = testing::run_program("viscera",
                                   "export " + testing::shell_quote(package_.string()) +
                                       " --format sofa -o " +
                                       testing::shell_quote(scene_.string()) + " --json",
                                   dir_);
    if (c.refused_object != nullptr) return;
    ASSERT_EQ(result_.exit_code, 0) << result_.err;
    scenario_ = core::read_package(package_);
    reader_ = std::make_unique<SofaSceneReader>(scene_);
  }

  /// Object ids of the scenario with a simulated body.
  std::vector<const core::SceneObject*> bodies() const {
    std::vector<const core::SceneObject*> found;
    for (const auto& o : scenario_.objects) {
      if ((o.body_kind == core::BodyKind::TetMesh || o.body_kind == core::BodyKind::MassSpring) &&
          !o.body.tets.empty())
        found.push_back(&o);
    }
    return found;
  }
  const SofaElement& node(const std::string& id) const {
    const SofaElement* n = reader_->body_node(id);
    EXPECT_NE(n, nullptr) << id;
    static const SofaElement empty;
    return n != nullptr ? *n : empty;
  }
  double solver(const std::string& type, const std::string& key) const {
    const SofaElement* e = reader_->root().child(type);
    EXPECT_NE(e, nullptr) << type;
    return e != nullptr ? std::stod(e->attribute(key)) : 0.0;
  }
  /// The interaction springs at the root: (object1 id, object2 id, springs).
  struct Link {
    std::string a, b;
    std::vector<double> values;
  };
  std::vector<Link> links() const {
    std::vector<Link> found;
    for (const SofaElement* s : reader_->root().children_of("SpringForceField")) {
      const auto id = [](std::string path) { return path.substr(1, path.find('/') - 1); };
      found.push_back(
          {id(s->attribute("object1")), id(s->attribute("object2")), s->numbers("spring")});
    }
    return found;
  }

  fs::path package_, dir_, scene_;
  testing::CommandResult result_;
  core::Scenario scenario_;
  std::unique_ptr<SofaSceneReader> reader_;
};

TEST_P(SofaTemplateExport, writes_into_missing_folders_a_scene_naming_its_sofa_release) {
  EXPECT_TRUE(fs::exists(scene_)) << "the missing output folders are created";
  EXPECT_NE(reader_->header_comment().find("sofa-version v26.06"), std::string::npos)
      << reader_->header_comment();
}

using SofaTemplateRefusal = SofaTemplateExport;

TEST_P(SofaTemplateRefusal, says_why_in_one_line_and_writes_nothing) {
  const TemplateCase& c = GetParam();
  EXPECT_EQ(result_.exit_code, 2) << result_.err;
  EXPECT_TRUE(testing::message_has(
      result_.err, {"object \"" + std::string(c.refused_object) + "\"", "no SOFA counterpart"}))
      << result_.err;
  EXPECT_EQ(std::count(result_.err.begin(), result_.err.end(), '\n'), 1) << result_.err;
  EXPECT_FALSE(fs::exists(dir_ / "not-yet")) << "a refused export leaves no folder behind";
}

TEST_P(SofaTemplateExport, spring_bodies_give_each_edge_visceras_constant_and_damping) {
  const double beta = solver("EulerImplicitSolver", "rayleighStiffness");
  int spring_bodies = 0;
  for (const core::SceneObject* o : bodies()) {
    if (o->body_kind != core::BodyKind::MassSpring) continue;
    ++spring_bodies;
    const auto expected = viscera_edges(scenario_, *o);
    const auto built = reader_->body_springs(node(o->id));
    ASSERT_EQ(built.size(), expected.size()) << o->id;
    for (const auto& s : built) {
      const auto& [k, c] = expected.at({std::min(s.a, s.b), std::max(s.a, s.b)});
      ASSERT_NEAR(s.stiffness, k, 0.01 * k) << o->id << " edge " << s.a << "-" << s.b;
      // Damping along the edge: the spring's own plus the solver's β K (K = ks u uᵀ at rest).
      ASSERT_NEAR(s.damping + beta * s.stiffness, c, 0.01 * c) << o->id;
    }
  }
  if (std::string(GetParam().template_name) == "laparoscopy-gyn") {
    EXPECT_GT(spring_bodies, 0);
  }
}

TEST_P(SofaTemplateExport, tet_bodies_carry_each_layers_own_material_and_damping) {
  const double beta = solver("EulerImplicitSolver", "rayleighStiffness");
  for (const core::SceneObject* o : bodies()) {
    if (o->body_kind != core::BodyKind::TetMesh) continue;
    const SofaElement* fem = node(o->id).child("TetrahedronFEMForceField");
    ASSERT_NE(fem, nullptr) << o->id;
    EXPECT_FALSE(fem->has("rayleighStiffness")) << "damping belongs on the ODE solver";
    const auto young = fem->numbers("youngModulus"), poisson = fem->numbers("poissonRatio");
    ASSERT_TRUE(young.size() == 1 || young.size() == o->body.tets.size()) << o->id;
    std::set<double> layers;
    const bool held = reader_->fixed(node(o->id)).size() == o->body.nodes.size();
    for (std::size_t t = 0; t < o->body.tets.size(); ++t) {
      const core::Material& m = material_of_tet(scenario_, *o, t);
      const auto e = exporters::sofa_elasticity(m);
      const double written = young.size() == 1 ? young[0] : young[t];
      ASSERT_NEAR(written, e.young_modulus, 1e-9 * e.young_modulus) << o->id << " tet " << t;
      ASSERT_NEAR(poisson.size() == 1 ? poisson[0] : poisson[t], e.poisson_ratio, 1e-12);
      layers.insert(written);
      if (!held) {
        EXPECT_NEAR(beta, m.distance_damping / m.distance_stiffness, 0.01 * beta);
      }
    }
    std::set<std::string> materials;
    for (std::size_t t = 0; t < o->body.tets.size(); ++t)
      materials.insert(material_of_tet(scenario_, *o, t).id);
    if (materials.size() > 1) {
      EXPECT_GT(layers.size(), 1u) << o->id << ": one E for its layers";
    }
  }
}

TEST_P(SofaTemplateExport, cg_stops_on_its_tolerance_for_the_scenes_masses_and_step) {
  const double h = scenario_.session.time_step;
  const double tolerance = solver("CGLinearSolver", "tolerance");
  const double threshold = solver("CGLinearSolver", "threshold");
  const double iterations = solver("CGLinearSolver", "iterations");
  const double beta = solver("EulerImplicitSolver", "rayleighStiffness");
  EXPECT_LE(tolerance, 1e-5);
  // pᵀAp ≥ m_min |p|² with A ⪰ M, and CG's last directions are about tolerance·|b|, |b| ≥ h
  // m_min g (EulerImplicitSolver.cpp, CGLinearSolver.inl).
  double m_min = INFINITY, a_max = 0.0;
  std::map<std::string, std::vector<double>> rows;
  for (const core::SceneObject* o : bodies()) {
    rows[o->id].assign(o->body.nodes.size(), 0.0);
    for (const auto& s : reader_->body_springs(node(o->id))) {
      rows[o->id][static_cast<std::size_t>(s.a)] += 2.0 * s.stiffness;
      rows[o->id][static_cast<std::size_t>(s.b)] += 2.0 * s.stiffness;
    }
  }
  for (const auto& link : links()) {
    for (std::size_t k = 0; k + 5 <= link.values.size(); k += 5) {
      rows[link.a][static_cast<std::size_t>(link.values[k])] += 2.0 * link.values[k + 2];
      rows[link.b][static_cast<std::size_t>(link.values[k + 1])] += 2.0 * link.values[k + 2];
    }
  }
  for (const core::SceneObject* o : bodies()) {
    const auto masses = reader_->masses(node(o->id));
    ASSERT_EQ(masses.size(), o->body.nodes.size()) << o->id;
    const auto fixed = reader_->fixed(node(o->id));
    const std::set<int> held(fixed.begin(), fixed.end());
    for (std::size_t i = 0; i < masses.size(); ++i) {
      if (held.contains(static_cast<int>(i))) continue;
      m_min = std::min(m_min, masses[i]);
      a_max = std::max(a_max, masses[i] + h * (h + beta) * rows[o->id][i]);
    }
  }
  ASSERT_TRUE(std::isfinite(m_min));
  const double g = std::max(scenario_.session.gravity.norm(), 9.81);
  const double smallest = m_min * std::pow(tolerance * h * m_min * g, 2);
  EXPECT_LE(threshold, 1e-3 * smallest) << "CG would stop on the threshold";
  EXPECT_GT(threshold, 0.0);
  // The threshold of the first exporter, 1e-12, is above these denominators: it stopped CG.
  EXPECT_LT(smallest, 1e-12);
  EXPECT_GE(iterations, 0.5 * std::sqrt(a_max / m_min) * std::log(2.0 / tolerance));
}

TEST_P(SofaTemplateExport, contact_scenes_have_the_whole_pipeline_at_the_sessions_stiffness) {
  const bool contact = scenario_.session.contact_stiffness > 0.0 && bodies().size() > 1;
  if (std::string(GetParam().label) == "ball_on_floor") {
    EXPECT_TRUE(contact);
  }
  const SofaElement& root = reader_->root();
  std::vector<std::string> types;
  testing::collect_component_types(root, types);
  const bool models = std::count(types.begin(), types.end(), "TriangleCollisionModel") > 0;
  if (!contact) {
    EXPECT_EQ(root.child("CollisionPipeline"), nullptr);
    EXPECT_FALSE(models);
    return;
  }
  for (const char* type :
       {"CollisionPipeline", "BruteForceBroadPhase", "BVHNarrowPhase", "CollisionResponse"})
    EXPECT_NE(root.child(type), nullptr) << type;
  const SofaElement* intersection = root.child("MinProximityIntersection");
  if (intersection == nullptr) intersection = root.child("LocalMinDistance");
  ASSERT_NE(intersection, nullptr);
  const double d0 = std::stod(intersection->attribute("contactDistance"));
  EXPECT_GT(std::stod(intersection->attribute("alarmDistance")), d0);
  std::vector<double> stiffness;
  for (const core::SceneObject* o : bodies()) {
    const SofaElement* collision = node(o->id).child("Node", "collision");
    ASSERT_NE(collision, nullptr) << o->id;
    for (const char* type : {"TriangleCollisionModel", "LineCollisionModel", "PointCollisionModel",
                             "MechanicalObject"})
      ASSERT_NE(collision->child(type), nullptr) << o->id << " " << type;
    EXPECT_NE(collision->child("SubsetMapping"), nullptr) << o->id;
    stiffness.push_back(
        std::stod(collision->child("TriangleCollisionModel")->attribute("contactStiffness")));
  }
  // BarycentricPenalityContact: k = k₁ k₂ / d0 per contact, for every pair of bodies.
  for (std::size_t i = 0; i < stiffness.size(); ++i) {
    for (std::size_t j = i + 1; j < stiffness.size(); ++j)
      EXPECT_NEAR(stiffness[i] * stiffness[j] / d0, scenario_.session.contact_stiffness,
                  0.01 * scenario_.session.contact_stiffness);
  }
}

TEST_P(SofaTemplateExport, attached_nodes_are_never_also_fixed_and_pathologies_hang_on_the_wall) {
  // object2 of each attachment is the attached part (Connection::object_b); a node of it that
  // were also fixed would never follow its host. (A host node may be held: the cervix is.)
  for (const auto& link : links()) {
    const auto fixed = reader_->fixed(node(link.b));
    const std::set<int> held(fixed.begin(), fixed.end());
    ASSERT_FALSE(link.values.empty());
    for (std::size_t k = 0; k + 5 <= link.values.size(); k += 5) {
      EXPECT_FALSE(held.contains(static_cast<int>(link.values[k + 1])))
          << link.b << " node " << link.values[k + 1] << " is fixed and attached";
    }
  }
  const std::vector<Link> attachments = links();
  for (const auto& pathology : scenario_.pathologies) {
    if (pathology.object.empty()) continue;
    EXPECT_TRUE(reader_->fixed(node(pathology.object)).empty()) << pathology.object;
    EXPECT_TRUE(std::any_of(
        attachments.begin(), attachments.end(),
        [&](const Link& l) { return l.a == pathology.host_object && l.b == pathology.object; }))
        << pathology.object << " is not attached to " << pathology.host_object;
  }
  if (std::string(GetParam().template_name) == "hysteroscopy") {
    EXPECT_FALSE(links().empty());
  }
}

TEST_P(SofaTemplateExport, plugins_are_declared_by_plugin_name_exactly_for_the_components_used) {
  EXPECT_EQ(reader_->plugins_without_plugin_name(), 0);
  std::vector<std::string> types;
  testing::collect_component_types(reader_->root(), types);
  std::set<std::string> needed;
  for (const auto& type : types) {
    const std::string plugin = plugin_of(type);
    if (!plugin.empty()) needed.insert(plugin);
  }
  const auto declared = reader_->plugins();
  EXPECT_EQ(std::set<std::string>(declared.begin(), declared.end()), needed);
  EXPECT_EQ(declared.size(), needed.size()) << "a plugin is declared twice";
}

TEST_P(SofaTemplateExport, every_link_resolves_to_one_element) {
  std::string problems;
  for (const auto& problem : testing::unresolved_links(reader_->root()))
    problems += problem + "\n";
  EXPECT_EQ(problems, "");
}

INSTANTIATE_TEST_SUITE_P(EveryTemplate, SofaTemplateExport, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<TemplateCase>& param_info) {
                           return std::string(param_info.param.label);
                         });
INSTANTIATE_TEST_SUITE_P(RefusedTemplate, SofaTemplateRefusal, ::testing::ValuesIn(kRefused),
                         [](const ::testing::TestParamInfo<TemplateCase>& param_info) {
                           return std::string(param_info.param.label);
                         });

}  // namespace
}  // namespace viscera
