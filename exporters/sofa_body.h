#pragma once
/// The simulated objects of a SOFA export, gathered once: masses, holds, attachments and the
/// force-field parameters of sofa_material.h for each body (SOFA v26.06). Internal to
/// exporters/.
///
/// Holds and attachments: a connection joins node pairs of object_a (the host, e.g. the uterus)
/// and object_b (the attached part, e.g. a polyp). The package may also flag the part's pair
/// nodes as fixed (templates/template_parts.cpp, attach()); in SOFA a node both fixed and
/// spring-linked never follows its host, so the part's attached nodes are written free and held
/// by the attachment springs alone (sofa_scene_exporter.h). A connection to an object left out
/// of the export is not written, and its nodes keep their fixed flags.

#include <optional>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "exporters/export_object.h"
#include "exporters/sofa_material.h"

namespace viscera::exporters {

/// One object with a simulated body, as the scene carries it.
struct SofaBody {
  const ExportObject* object = nullptr;
  bool mass_spring = false;            ///< KisMo springs, else TetrahedronFEMForceField
  std::vector<double> masses;          ///< kg per node (the package's, or lumped from density)
  std::optional<double> mass_density;  ///< kg/m³ when DiagonalMass massDensity gives `masses`
  std::vector<int> fixed;              ///< FixedProjectiveConstraint indices, ascending
  std::vector<int> attached;           ///< nodes held by attachment springs, ascending
  /// TetrahedronFEMForceField: one value, or one per tet when the layers differ.
  std::vector<double> young_modulus, poisson_ratio;
  std::vector<SofaSpring> springs;  ///< KisMo edge springs (damping carried by Rayleigh β)
  std::optional<double> tetrahedra_stiffness;  ///< MeshSpringForceField S when one value does
  std::vector<double> tet_rayleigh;            ///< β (s) of each tet's material
  std::vector<double> tet_mass;                ///< kg of each tet (density × volume)
  std::vector<double> node_stiffness;          ///< N/m, Gershgorin row sum of the body's stiffness
  bool all_fixed = false;                      ///< every node held (a fixture such as a floor)
};

/// The bodies of `objects` in order. Throws core::UsageError naming the object for a body kind
/// SOFA has no counterpart for (the urethra lattice of seed 002, cell-agent tissue of seed
/// 003), and core::InputError for unknown materials or non-positive stiffness.
std::vector<SofaBody> sofa_bodies(const core::Scenario& scenario,
                                  const std::vector<ExportObject>& objects);

/// The connections whose two objects are both exported bodies, in scenario order.
std::vector<const core::Connection*> exported_connections(const core::Scenario& scenario,
                                                          const std::vector<SofaBody>& bodies);

/// The body of object `id`, or nullptr.
const SofaBody* find_body(const std::vector<SofaBody>& bodies, const std::string& id);

}  // namespace viscera::exporters
