#pragma once
/// A small reader of SOFA scenes that gives what SOFA v26.06 builds from them, from the
/// components' semantics in SOFA's source (SOFA itself is not installable here):
///   MeshSpringForceField.inl  tetrahedraStiffness S (alias tetrasStiffness): one spring per tet
///                             edge of the node's topology, each edge once, stiffness S / l0
///   SpringForceField.inl      "i j ks kd L" per spring, f = (ks (l − L) + kd l̇) u
///   DiagonalMass              massDensity ρ: ρ V / 4 of each tet on its nodes; or vertexMass
///   RequiredPlugin.cpp        `pluginName` (a list); `name` only when pluginName is not set
///   BarycentricPenalityContact.inl  contact stiffness k₁ k₂ / (contactDistance + proximities)

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace viscera::testing {

/// One XML element of the scene: a Node or a component.
struct SofaElement {
  std::string type;  ///< "Node" or the component class
  std::map<std::string, std::string> attributes;
  std::vector<SofaElement> children;

  std::string attribute(const std::string& key) const;  ///< "" when absent
  bool has(const std::string& key) const { return attributes.contains(key); }
  /// The first child of `type` (with `name` when given), or nullptr.
  const SofaElement* child(const std::string& type, const std::string& name = "") const;
  std::vector<const SofaElement*> children_of(const std::string& type) const;
  std::vector<double> numbers(const std::string& key) const;
  std::vector<int> integers(const std::string& key) const;
};

/// One spring as SOFA stores it.
struct SofaBuiltSpring {
  int a = 0, b = 0;
  double stiffness = 0.0, damping = 0.0, rest_length = 0.0;
};

class SofaSceneReader {
 public:
  /// Parses `scene`; fails the test (ADD_FAILURE) when it is not well-formed XML.
  explicit SofaSceneReader(const std::filesystem::path& scene);

  const SofaElement& root() const { return root_; }
  /// The text of the first XML comment of the file.
  const std::string& header_comment() const { return header_; }

  /// The child node `name` of the root, or nullptr.
  const SofaElement* body_node(const std::string& name) const;
  /// The tet mesh the node's MeshVTKLoader reads (path relative to the scene).
  core::TetMesh loaded_mesh(const SofaElement& node) const;
  /// The springs the node's MeshSpringForceField or SpringForceField builds (empty when none).
  std::vector<SofaBuiltSpring> body_springs(const SofaElement& node) const;
  /// The node masses DiagonalMass gives, kg.
  std::vector<double> masses(const SofaElement& node) const;
  /// FixedProjectiveConstraint indices (empty when none).
  std::vector<int> fixed(const SofaElement& node) const;

  /// Plugin names the scene requires, and the RequiredPlugin elements without pluginName.
  std::vector<std::string> plugins() const;
  int plugins_without_plugin_name() const;

 private:
  std::filesystem::path path_;
  SofaElement root_;
  std::string header_;
};

/// Problems with the scene's links, as SOFA resolves them (a component or node path relative to
/// the node holding the link, ".." for the parent): every "@…" value of the link attributes
/// (src, input, output, object1, object2) must name exactly one element, and no two elements
/// of a node may share a name. Empty when every link resolves.
std::vector<std::string> unresolved_links(const SofaElement& root);

/// Every component type used anywhere under `element` (Node excluded).
void collect_component_types(const SofaElement& element, std::vector<std::string>& types);

}  // namespace viscera::testing
