#include "tests/exporters/sofa_scene_reader.h"

#include <gtest/gtest.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "importers/mesh_reader.h"

namespace viscera::testing {
namespace {

SofaElement convert(vtkXMLDataElement* e) {
  SofaElement out;
  out.type = e->GetName();
  for (int i = 0; i < e->GetNumberOfAttributes(); ++i)
    out.attributes[e->GetAttributeName(i)] = e->GetAttributeValue(i);
  for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
    out.children.push_back(convert(e->GetNestedElement(i)));
  return out;
}

}  // namespace

std::string SofaElement::attribute(const std::string& key) const {
  const auto it = attributes.find(key);
  return it == attributes.end() ? std::string() : it->second;
}

const SofaElement* SofaElement::child(const std::string& wanted, const std::string& name) const {
  for (const auto& c : children) {
    if (c.type == wanted && (name.empty() || c.attribute("name") == name)) return &c;
  }
  return nullptr;
}

std::vector<const SofaElement*> SofaElement::children_of(const std::string& wanted) const {
  std::vector<const SofaElement*> found;
  for (const auto& c : children)
    if (c.type == wanted) found.push_back(&c);
  return found;
}

std::vector<double> SofaElement::numbers(const std::string& key) const {
  std::istringstream in(attribute(key));
  std::vector<double> values;
  for (double v; in >> v;)
    values.push_back(v);
  return values;
}

std::vector<int> SofaElement::integers(const std::string& key) const {
  std::istringstream in(attribute(key));
  std::vector<int> values;
  for (int v; in >> v;)
    values.push_back(v);
  return values;
}

SofaSceneReader::SofaSceneReader(const std::filesystem::path& scene) : path_(scene) {
  const auto element = vtkSmartPointer<vtkXMLDataElement>::Take(
      vtkXMLUtilities::ReadElementFromFile(scene.string().c_str()));
  if (element == nullptr) {
    ADD_FAILURE() << scene << " is not well-formed XML";
    return;
  }
  root_ = convert(element);
  std::ifstream in(scene);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto begin = text.find("<!--"), end = text.find("-->");
  if (begin != std::string::npos && end != std::string::npos && end > begin)
    header_ = text.substr(begin + 4, end - begin - 4);
}

const SofaElement* SofaSceneReader::body_node(const std::string& name) const {
  return root_.child("Node", name);
}

core::TetMesh SofaSceneReader::loaded_mesh(const SofaElement& node) const {
  const SofaElement* loader = node.child("MeshVTKLoader");
  if (loader == nullptr) return {};
  return importers::read_tet_mesh(path_.parent_path() / loader->attribute("filename"));
}

std::vector<SofaBuiltSpring> SofaSceneReader::body_springs(const SofaElement& node) const {
  std::vector<SofaBuiltSpring> springs;
  if (const SofaElement* mesh_springs = node.child("MeshSpringForceField")) {
    // MeshSpringForceField::init with only tetrahedra: each tet edge once, S / l0 and D / l0.
    const std::string key =
        mesh_springs->has("tetrahedraStiffness") ? "tetrahedraStiffness" : "tetrasStiffness";
    const std::string damping_key =
        mesh_springs->has("tetrahedraDamping") ? "tetrahedraDamping" : "tetrasDamping";
    const double s = std::stod(mesh_springs->attribute(key));
    const double d =
        mesh_springs->has(damping_key) ? std::stod(mesh_springs->attribute(damping_key)) : 0.0;
    const core::TetMesh mesh = loaded_mesh(node);
    std::set<std::pair<int, int>> seen;
    for (const auto& tet : mesh.tets) {
      for (int a = 0; a < 4; ++a) {
        for (int b = a + 1; b < 4; ++b) {
          const int i = std::min(tet[a], tet[b]), j = std::max(tet[a], tet[b]);
          if (!seen.insert({i, j}).second) continue;
          const double l =
              (mesh.nodes[static_cast<std::size_t>(j)] - mesh.nodes[static_cast<std::size_t>(i)])
                  .norm();
          springs.push_back({i, j, s / l, d / l, l});
        }
      }
    }
    return springs;
  }
  if (const SofaElement* list = node.child("SpringForceField")) {
    const std::vector<double> v = list->numbers("spring");
    for (std::size_t k = 0; k + 5 <= v.size(); k += 5) {
      springs.push_back(
          {static_cast<int>(v[k]), static_cast<int>(v[k + 1]), v[k + 2], v[k + 3], v[k + 4]});
    }
  }
  return springs;
}

std::vector<double> SofaSceneReader::masses(const SofaElement& node) const {
  const SofaElement* mass = node.child("DiagonalMass");
  if (mass == nullptr) return {};
  if (mass->has("vertexMass")) return mass->numbers("vertexMass");
  return core::lumped_node_masses(loaded_mesh(node), std::stod(mass->attribute("massDensity")));
}

std::vector<int> SofaSceneReader::fixed(const SofaElement& node) const {
  const SofaElement* constraint = node.child("FixedProjectiveConstraint");
  return constraint == nullptr ? std::vector<int>{} : constraint->integers("indices");
}

std::vector<std::string> SofaSceneReader::plugins() const {
  std::vector<std::string> names;
  for (const SofaElement* p : root_.children_of("RequiredPlugin")) {
    std::istringstream in(p->has("pluginName") ? p->attribute("pluginName") : p->attribute("name"));
    for (std::string name; in >> name;)
      names.push_back(name);
  }
  return names;
}

int SofaSceneReader::plugins_without_plugin_name() const {
  int count = 0;
  for (const SofaElement* p : root_.children_of("RequiredPlugin"))
    count += p->has("pluginName") ? 0 : 1;
  return count;
}

namespace {

void check_links(const std::vector<const SofaElement*>& path, std::vector<std::string>& problems) {
  const SofaElement& node = *path.back();
  std::map<std::string, int> names;
  for (const auto& c : node.children)
    if (c.has("name")) ++names[c.attribute("name")];
  for (const auto& [name, count] : names)
    if (count > 1) problems.push_back("two elements named \"" + name + "\" in one node");
  for (const auto& c : node.children) {
    for (const char* key : {"src", "input", "output", "object1", "object2"}) {
      const std::string link = c.attribute(key);
      if (link.empty() || link[0] != '@') continue;
      std::vector<const SofaElement*> at = path;
      std::istringstream parts(link.substr(1));
      std::vector<std::string> segments;
      for (std::string segment; std::getline(parts, segment, '/');)
        segments.push_back(segment);
      bool found = !segments.empty();
      for (std::size_t i = 0; found && i < segments.size(); ++i) {
        if (segments[i] == "..") {
          found = at.size() > 1;
          if (found) at.pop_back();
          continue;
        }
        int matches = 0;
        const SofaElement* next = nullptr;
        for (const auto& candidate : at.back()->children) {
          if (candidate.attribute("name") == segments[i]) {
            ++matches;
            next = &candidate;
          }
        }
        found = matches == 1 && (i + 1 == segments.size() || next->type == "Node");
        if (found && next->type == "Node") at.push_back(next);
      }
      if (!found) problems.push_back(c.type + " " + key + "=\"" + link + "\" does not resolve");
    }
    if (c.type == "Node") {
      std::vector<const SofaElement*> deeper = path;
      deeper.push_back(&c);
      check_links(deeper, problems);
    }
  }
}

}  // namespace

std::vector<std::string> unresolved_links(const SofaElement& root) {
  std::vector<std::string> problems;
  check_links({&root}, problems);
  return problems;
}

void collect_component_types(const SofaElement& element, std::vector<std::string>& types) {
  for (const auto& c : element.children) {
    if (c.type == "Node")
      collect_component_types(c, types);
    else
      types.push_back(c.type);
  }
}

}  // namespace viscera::testing
