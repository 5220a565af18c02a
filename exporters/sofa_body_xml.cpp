// The per-object nodes of the SOFA scene (sofa_scene_parts.h).
#include <charconv>
#include <map>
#include <set>

#include "core/error.h"
#include "exporters/sofa_scene_parts.h"

namespace viscera::exporters {
namespace {

void write_visual(SofaXml& xml, const ExportObject& object, const std::string& folder,
                  const std::string& indent, bool mapped) {
  xml.text += indent + "<Node name=\"visual\">\n";
  const std::string inner = indent + "  ";
  xml.element(inner, "MeshOBJLoader",
              " name=\"surface\" filename=\"" +
                  xml_escaped(folder + "/" + object.id() + "_surface.obj") +
                  "\" handleSeams=\"1\"");
  std::string model = " name=\"model\" src=\"@surface\"";
  if (object.maps.contains("albedo")) {
    model +=
        " texturename=\"" +
        xml_escaped(folder + "/" + object.id() + "_surface_" + object.texture_id + "_albedo.png") +
        "\"";
  }
  xml.element(inner, "OglModel", model);
  if (mapped)
    xml.element(inner, "BarycentricMapping",
                " name=\"embedding\" input=\"@../dofs\" output=\"@model\"");
  xml.text += indent + "</Node>\n";
}

/// The body's boundary as its own point set mapped onto the body's nodes (SubsetMapping), with
/// triangle, line and point collision models carrying √(k_V d0) each.
void write_collision(SofaXml& xml, const SofaBody& body, const SofaContact& contact) {
  const core::TetMesh& mesh = body.object->source->body;
  const std::vector<core::Triangle> faces = body_surface(mesh);
  std::map<int, int> local;
  for (const auto& f : faces)
    for (const int v : f)
      local.emplace(v, 0);
  std::vector<int> subset;
  std::vector<double> positions;
  for (auto& [node, index] : local) {
    index = static_cast<int>(subset.size());
    subset.push_back(node);
    for (int k = 0; k < 3; ++k)
      positions.push_back(mesh.nodes[static_cast<std::size_t>(node)][k]);
  }
  std::vector<int> triangles;
  for (const auto& f : faces)
    for (const int v : f)
      triangles.push_back(local.at(v));
  const std::string in = "      ";
  xml.text += "    <Node name=\"collision\">\n";
  xml.element(in, "MeshTopology",
              " name=\"surface\" triangles=\"" + sofa_indices(triangles) + "\"");
  xml.element(
      in, "MechanicalObject",
      " name=\"surface_dofs\" template=\"Vec3d\" position=\"" + sofa_numbers(positions) + "\"");
  std::string model = " contactStiffness=\"" + sofa_number(contact.model_stiffness) + "\"";
  if (body.all_fixed) model += " moving=\"0\" simulated=\"0\"";
  xml.element(in, "TriangleCollisionModel", " name=\"triangles\"" + model);
  xml.element(in, "LineCollisionModel", " name=\"lines\"" + model);
  xml.element(in, "PointCollisionModel", " name=\"points\"" + model);
  xml.element(in, "SubsetMapping",
              " name=\"boundary\" input=\"@../dofs\" output=\"@surface_dofs\" indices=\"" +
                  sofa_indices(subset) + "\"");
  xml.text += "    </Node>\n";
}

void write_force_field(SofaXml& xml, const SofaBody& body) {
  const std::string in = "    ";
  if (!body.mass_spring) {
    xml.element(in, "TetrahedronFEMForceField",
                " name=\"fem\" method=\"large\" youngModulus=\"" +
                    sofa_numbers(body.young_modulus) + "\" poissonRatio=\"" +
                    sofa_numbers(body.poisson_ratio) + "\"");
    return;
  }
  if (body.tetrahedra_stiffness) {
    // MeshSpringForceField.inl: each tet edge once, stiffness S / l0.
    xml.element(in, "MeshSpringForceField",
                " name=\"springs\" tetrahedraStiffness=\"" +
                    sofa_number(*body.tetrahedra_stiffness) + "\" tetrahedraDamping=\"0\"");
    return;
  }
  std::string springs;
  for (const auto& s : body.springs) {
    springs += (springs.empty() ? "" : "  ") + std::to_string(s.a) + " " + std::to_string(s.b) +
               " " + sofa_number(s.stiffness) + " " + sofa_number(s.damping) + " " +
               sofa_number(s.rest_length);
  }
  xml.element(in, "SpringForceField",
              " name=\"springs\" template=\"Vec3d\" object1=\"@dofs\" object2=\"@dofs\" spring=\"" +
                  springs + "\"");
}

}  // namespace

void write_body_node(SofaXml& xml, const SofaBody& body, const SofaContact& contact,
                     const std::string& folder) {
  const ExportObject& object = *body.object;
  const std::string in = "    ";
  xml.text += "  <Node name=\"" + xml_escaped(object.id()) + "\">\n";
  xml.element(in, "MeshVTKLoader",
              " name=\"loader\" filename=\"" +
                  xml_escaped(folder + "/" + object.id() + "_body.vtk") + "\"");
  xml.element(in, "MeshTopology", " name=\"topology\" src=\"@loader\"");
  xml.element(in, "MechanicalObject", " name=\"dofs\" template=\"Vec3d\" src=\"@loader\"");
  if (body.mass_density)
    xml.element(in, "DiagonalMass",
                " name=\"mass\" massDensity=\"" + sofa_number(*body.mass_density) + "\"");
  else
    xml.element(in, "DiagonalMass",
                " name=\"mass\" vertexMass=\"" + sofa_numbers(body.masses) + "\"");
  write_force_field(xml, body);
  if (!body.fixed.empty())
    xml.element(in, "FixedProjectiveConstraint",
                " name=\"fixed\" indices=\"" + sofa_indices(body.fixed) + "\"");
  if (contact.enabled) write_collision(xml, body, contact);
  write_visual(xml, object, folder, in, true);
  xml.text += "  </Node>\n";
}

void write_static_node(SofaXml& xml, const ExportObject& object, const std::string& folder) {
  xml.text += "  <Node name=\"" + xml_escaped(object.id()) + "\">\n";
  write_visual(xml, object, folder, "    ", false);
  xml.text += "  </Node>\n";
}

}  // namespace viscera::exporters
