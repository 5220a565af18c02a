#include "exporters/sofa_scene_exporter.h"

#include <charconv>
#include <map>

#include "exporters/sofa_scene_parts.h"

namespace viscera::exporters {
namespace {

/// Text safe inside an XML comment, which may not contain "--".
std::string comment_safe(std::string text) {
  for (std::size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at))
    text.replace(at, 2, "- -");
  return text;
}

std::string header(const core::Scenario& scenario, const SofaSolverSettings& solver,
                   const SofaContact& contact) {
  std::string text = "<!-- " + comment_safe(scenario.metadata.name) +
                     ": exported by Viscera (exporters/sofa_scene_exporter.h).\n";
  text += "     sofa-version " + std::string(kSofaRelease) + ": written for SOFA " + kSofaRelease +
          " (component names and data of that release; open with runSofa on this file).\n";
  text +=
      "     Materials: exporters/sofa_material.h. Solver: exporters/sofa_solver_settings.h;"
      " estimated smallest pTAp " +
      sofa_number(solver.smallest_denominator) + " kg m2/s2.\n";
  if (!solver.rayleigh_exact) {
    text +=
        "     The bodies' materials damp with different Rayleigh coefficients; the one solver"
        " takes their mass-weighted mean.\n";
  }
  if (contact.enabled) {
    text += "     Contact: " + sofa_number(contact.stiffness) +
            " N/m per contact = contactStiffness^2 / contactDistance.\n";
  }
  return text + "-->\n";
}

void write_collision_pipeline(SofaXml& xml, const SofaContact& contact) {
  xml.element("  ", "CollisionPipeline", " name=\"pipeline\"");
  xml.element("  ", "BruteForceBroadPhase", " name=\"broadphase\"");
  xml.element("  ", "BVHNarrowPhase", " name=\"narrowphase\"");
  xml.element("  ", "MinProximityIntersection",
              " name=\"intersection\" alarmDistance=\"" + sofa_number(contact.alarm_distance) +
                  "\" contactDistance=\"" + sofa_number(contact.contact_distance) + "\"");
  xml.element("  ", "CollisionResponse",
              " name=\"response\" response=\"PenalityContactForceField\"");
}

void write_connection(SofaXml& xml, const core::Scenario& scenario,
                      const core::Connection& connection) {
  const auto& a = scenario.find_object(connection.object_a)->body.nodes;
  const auto& b = scenario.find_object(connection.object_b)->body.nodes;
  std::string springs;
  for (const auto& [i, j] : connection.node_pairs) {
    const double rest = (a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(j)]).norm();
    springs += (springs.empty() ? "" : "  ") + std::to_string(i) + " " + std::to_string(j) + " " +
               sofa_number(connection.stiffness) + " 0 " + sofa_number(rest);
  }
  xml.element("  ", "SpringForceField",
              " name=\"" + xml_escaped(connection.id) + "\" template=\"Vec3d\" object1=\"@" +
                  xml_escaped(connection.object_a) + "/dofs\" object2=\"@" +
                  xml_escaped(connection.object_b) + "/dofs\" spring=\"" + springs + "\"");
}

}  // namespace

void SofaXml::element(const std::string& indent, const std::string& type,
                      const std::string& attributes) {
  components.insert(type);
  text += indent + "<" + type + attributes + "/>\n";
}

std::string sofa_number(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string sofa_numbers(const std::vector<double>& values) {
  std::string text;
  for (const double v : values)
    text += (text.empty() ? "" : " ") + sofa_number(v);
  return text;
}

std::string sofa_indices(const std::vector<int>& values) {
  std::string text;
  for (const int v : values)
    text += (text.empty() ? "" : " ") + std::to_string(v);
  return text;
}

std::string xml_escaped(const std::string& text) {
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

std::string sofa_plugin_of(const std::string& type) {
  static const std::map<std::string, std::string> plugins = {
      {"MeshVTKLoader", "Sofa.Component.IO.Mesh"},
      {"MeshOBJLoader", "Sofa.Component.IO.Mesh"},
      {"MeshTopology", "Sofa.Component.Topology.Container.Constant"},
      {"MechanicalObject", "Sofa.Component.StateContainer"},
      {"DiagonalMass", "Sofa.Component.Mass"},
      {"TetrahedronFEMForceField", "Sofa.Component.SolidMechanics.FEM.Elastic"},
      {"MeshSpringForceField", "Sofa.Component.SolidMechanics.Spring"},
      {"SpringForceField", "Sofa.Component.SolidMechanics.Spring"},
      {"FixedProjectiveConstraint", "Sofa.Component.Constraint.Projective"},
      {"EulerImplicitSolver", "Sofa.Component.ODESolver.Backward"},
      {"CGLinearSolver", "Sofa.Component.LinearSolver.Iterative"},
      {"BarycentricMapping", "Sofa.Component.Mapping.Linear"},
      {"SubsetMapping", "Sofa.Component.Mapping.Linear"},
      {"OglModel", "Sofa.GL.Component.Rendering3D"},
      {"CollisionPipeline", "Sofa.Component.Collision.Detection.Algorithm"},
      {"BruteForceBroadPhase", "Sofa.Component.Collision.Detection.Algorithm"},
      {"BVHNarrowPhase", "Sofa.Component.Collision.Detection.Algorithm"},
      {"MinProximityIntersection", "Sofa.Component.Collision.Detection.Intersection"},
      {"CollisionResponse", "Sofa.Component.Collision.Response.Contact"},
      {"TriangleCollisionModel", "Sofa.Component.Collision.Geometry"},
      {"LineCollisionModel", "Sofa.Component.Collision.Geometry"},
      {"PointCollisionModel", "Sofa.Component.Collision.Geometry"},
  };
  const auto it = plugins.find(type);
  return it == plugins.end() ? std::string() : it->second;
}

std::string sofa_scene_xml(const core::Scenario& scenario, const std::vector<ExportObject>& objects,
                           const std::string& folder) {
  const std::vector<SofaBody> bodies = sofa_bodies(scenario, objects);
  const SofaContact contact = sofa_contact(scenario, bodies);
  const SofaSolverSettings solver = sofa_solver_settings(scenario, bodies, contact);

  SofaXml body;
  body.element("  ", "DefaultAnimationLoop", " name=\"animation\"");
  if (contact.enabled) write_collision_pipeline(body, contact);
  body.element("  ", "EulerImplicitSolver",
               " name=\"odesolver\" rayleighStiffness=\"" + sofa_number(solver.rayleigh_stiffness) +
                   "\" rayleighMass=\"0\"");
  body.element("  ", "CGLinearSolver",
               " name=\"linearsolver\" iterations=\"" + std::to_string(solver.iterations) +
                   "\" tolerance=\"" + sofa_number(solver.tolerance) + "\" threshold=\"" +
                   sofa_number(solver.threshold) + "\"");
  for (const auto& object : objects) {
    const SofaBody* simulated = find_body(bodies, object.id());
    if (simulated != nullptr)
      write_body_node(body, *simulated, contact, folder);
    else
      write_static_node(body, object, folder);
  }
  for (const core::Connection* connection : exported_connections(scenario, bodies))
    write_connection(body, scenario, *connection);

  const auto& session = scenario.session;
  std::string xml = "<?xml version=\"1.0\"?>\n" + header(scenario, solver, contact);
  xml += "<Node name=\"root\" dt=\"" + sofa_number(session.time_step) + "\" gravity=\"" +
         sofa_number(session.gravity.x()) + " " + sofa_number(session.gravity.y()) + " " +
         sofa_number(session.gravity.z()) + "\">\n";
  std::set<std::string> plugins;
  for (const auto& type : body.components) {
    const std::string plugin = sofa_plugin_of(type);
    if (!plugin.empty()) plugins.insert(plugin);
  }
  for (const auto& plugin : plugins)
    xml += "  <RequiredPlugin pluginName=\"" + plugin + "\"/>\n";
  xml += body.text;
  xml += "</Node>\n";
  return xml;
}

}  // namespace viscera::exporters
