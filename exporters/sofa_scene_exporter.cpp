#include "exporters/sofa_scene_exporter.h"

#include <charconv>
#include <cmath>

#include "exporters/sofa_material.h"

namespace viscera::exporters {
namespace {

std::string number(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string vector_text(const core::Vec3& v) {
  return number(v.x()) + " " + number(v.y()) + " " + number(v.z());
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

/// True when the package's node masses are the lumped density·V/4 of `material`.
bool masses_follow_density(const core::TetMesh& body, double density) {
  if (body.node_mass.empty()) return true;
  const std::vector<double> lumped = core::lumped_node_masses(body, density);
  for (std::size_t i = 0; i < lumped.size(); ++i) {
    if (std::abs(lumped[i] - body.node_mass[i]) > 1e-9 * std::max(std::abs(lumped[i]), 1e-30))
      return false;
  }
  return true;
}

void add_body(std::string& xml, const ExportObject& object, const std::string& folder) {
  const core::SceneObject& source = *object.source;
  const core::TetMesh& body = source.body;
  const core::Material material = object.material != nullptr ? *object.material : core::Material{};
  xml += "    <MeshVTKLoader name=\"loader\" filename=\"" +
         escaped(folder + "/" + object.id() + "_body.vtk") + "\"/>\n";
  xml += "    <MeshTopology name=\"topology\" src=\"@loader\"/>\n";
  xml += "    <MechanicalObject name=\"dofs\" template=\"Vec3d\" src=\"@loader\"/>\n";
  if (masses_follow_density(body, material.density)) {
    xml += "    <DiagonalMass name=\"mass\" massDensity=\"" + number(material.density) + "\"/>\n";
  } else {
    xml += "    <DiagonalMass name=\"mass\" vertexMass=\"";
    for (std::size_t i = 0; i < body.node_mass.size(); ++i)
      xml += (i > 0 ? " " : "") + number(body.node_mass[i]);
    xml += "\"/>\n";
  }
  if (source.body_kind == core::BodyKind::MassSpring) {
    const SofaSprings springs = sofa_springs(material, body);
    xml += "    <MeshSpringForceField name=\"springs\" tetrasStiffness=\"" +
           number(springs.stiffness) + "\" tetrasDamping=\"" + number(springs.damping) + "\"/>\n";
  } else {
    const SofaElasticity fem = sofa_elasticity(material);
    xml += "    <TetrahedronFEMForceField name=\"fem\" method=\"large\" youngModulus=\"" +
           number(fem.young_modulus) + "\" poissonRatio=\"" + number(fem.poisson_ratio) +
           "\" rayleighStiffness=\"" + number(fem.rayleigh_stiffness) + "\"/>\n";
  }
  std::string fixed;
  for (std::size_t i = 0; i < body.fixed.size(); ++i) {
    if (body.fixed[i] != 0) fixed += (fixed.empty() ? "" : " ") + std::to_string(i);
  }
  if (!fixed.empty())
    xml += "    <FixedProjectiveConstraint name=\"fixed\" indices=\"" + fixed + "\"/>\n";
}

void add_visual(std::string& xml, const ExportObject& object, const std::string& folder,
                const std::string& indent, bool mapped) {
  xml += indent + "<Node name=\"visual\">\n";
  xml += indent + "  <MeshOBJLoader name=\"surface\" filename=\"" +
         escaped(folder + "/" + object.id() + "_surface.obj") + "\" handleSeams=\"1\"/>\n";
  xml += indent + "  <OglModel name=\"model\" src=\"@surface\"";
  if (object.maps.contains("albedo")) {
    xml += " texturename=\"" +
           escaped(folder + "/" + object.id() + "_surface_" + object.texture_id + "_albedo.png") +
           "\"";
  }
  xml += "/>\n";
  if (mapped)
    xml += indent +
           "  <BarycentricMapping name=\"embedding\" input=\"@../dofs\" output=\"@model\"/>\n";
  xml += indent + "</Node>\n";
}

}  // namespace

std::string sofa_scene_xml(const core::Scenario& scenario, const std::vector<ExportObject>& objects,
                           const std::string& folder) {
  const auto& session = scenario.session;
  std::string xml = "<?xml version=\"1.0\"?>\n";
  xml += "<!-- " + escaped(scenario.metadata.name) +
         ": exported by Viscera; materials mapped as in exporters/sofa_material.h -->\n";
  xml += "<Node name=\"root\" dt=\"" + number(session.time_step) + "\" gravity=\"" +
         vector_text(session.gravity) + "\">\n";
  for (const char* plugin :
       {"Sofa.Component.IO.Mesh", "Sofa.Component.Topology.Container.Constant",
        "Sofa.Component.StateContainer", "Sofa.Component.Mass",
        "Sofa.Component.SolidMechanics.FEM.Elastic", "Sofa.Component.SolidMechanics.Spring",
        "Sofa.Component.Constraint.Projective", "Sofa.Component.ODESolver.Backward",
        "Sofa.Component.LinearSolver.Iterative", "Sofa.Component.Mapping.Linear",
        "Sofa.GL.Component.Rendering3D", "Sofa.Component.AnimationLoop"}) {
    xml += "  <RequiredPlugin name=\"" + std::string(plugin) + "\"/>\n";
  }
  xml += "  <DefaultAnimationLoop/>\n";
  xml += "  <EulerImplicitSolver name=\"odesolver\" rayleighMass=\"0\"/>\n";
  xml +=
      "  <CGLinearSolver name=\"linearsolver\" iterations=\"100\" tolerance=\"1e-9\" "
      "threshold=\"1e-12\"/>\n";
  std::vector<std::string> bodies;
  for (const auto& object : objects) {
    const bool simulated =
        object.has_body() && object.source->body_kind != core::BodyKind::CellAgent;
    xml += "  <Node name=\"" + escaped(object.id()) + "\">\n";
    if (simulated) {
      add_body(xml, object, folder);
      bodies.push_back(object.id());
    }
    add_visual(xml, object, folder, "    ", simulated);
    xml += "  </Node>\n";
  }
  for (const auto& connection : scenario.connections) {
    const auto exported = [&](const std::string& id) {
      return std::find(bodies.begin(), bodies.end(), id) != bodies.end();
    };
    if (!exported(connection.object_a) || !exported(connection.object_b)) continue;
    const auto& a = scenario.find_object(connection.object_a)->body.nodes;
    const auto& b = scenario.find_object(connection.object_b)->body.nodes;
    xml += "  <SpringForceField name=\"" + escaped(connection.id) +
           "\" template=\"Vec3d\" object1=\"@" + escaped(connection.object_a) +
           "/dofs\" object2=\"@" + escaped(connection.object_b) + "/dofs\" spring=\"";
    for (std::size_t p = 0; p < connection.node_pairs.size(); ++p) {
      const auto [i, j] = connection.node_pairs[p];
      const double rest = (a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(j)]).norm();
      xml += (p > 0 ? "  " : "") + std::to_string(i) + " " + std::to_string(j) + " " +
             number(connection.stiffness) + " 0 " + number(rest);
    }
    xml += "\"/>\n";
  }
  xml += "</Node>\n";
  return xml;
}

}  // namespace viscera::exporters
