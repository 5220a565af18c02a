#pragma once
/// Pieces of the SOFA scene XML (sofa_scene_exporter.h), internal to exporters/: a writer that
/// records the components it writes so that the scene requires exactly their plugins.

#include <set>
#include <string>
#include <vector>

#include "exporters/sofa_body.h"
#include "exporters/sofa_solver_settings.h"

namespace viscera::exporters {

/// Accumulates elements; `components` names every component type written.
struct SofaXml {
  std::string text;
  std::set<std::string> components;

  /// `<type name="…" attributes/>` on its own line; `attributes` is already escaped, e.g.
  /// ` dt="0.001"` (leading space included).
  void element(const std::string& indent, const std::string& type, const std::string& attributes);
};

/// Shortest round-trip decimal text of `value`.
std::string sofa_number(double value);
/// Space-separated values.
std::string sofa_numbers(const std::vector<double>& values);
std::string sofa_indices(const std::vector<int>& values);
/// Text escaped for an XML attribute.
std::string xml_escaped(const std::string& text);

/// The node of one simulated body: loader, topology, state, mass, force field, holds, the
/// collision surface when `contact.enabled`, and its mapped visual model.
void write_body_node(SofaXml& xml, const SofaBody& body, const SofaContact& contact,
                     const std::string& folder);
/// The node of an object without a simulated body: a static visual model.
void write_static_node(SofaXml& xml, const ExportObject& object, const std::string& folder);

/// The SOFA plugin (module) that registers component `type` in v26.06; empty for the components
/// of Sofa.Simulation.Core, which is always loaded (DefaultAnimationLoop).
std::string sofa_plugin_of(const std::string& type);

}  // namespace viscera::exporters
