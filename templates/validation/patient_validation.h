#pragma once
/// Validation of a generated virtual patient (issue 6 §3): the checks every draw of the variant
/// generator must pass before it is written out. Geometry only; the simulated second lives in
/// templates/generator/simulation_check.h, which may link the simulator.
///
/// | check         | passes when                                                                |
/// |---------------|----------------------------------------------------------------------------|
/// | surfaces      | the surface of every tet-bodied object is closed, consistently and outward  |
/// |               | oriented and free of self-intersections (CGAL PMP does_self_intersect);     |
/// |               | every vertex of every surface is finite                                     |
/// | overlap       | no two objects' surfaces cross (CGAL PMP do_intersect); two pathologies     |
/// |               | also may not hold one another                                               |
/// | tets          | every tet body has no inverted tet and its smallest dihedral angle is at    |
/// |               | least ValidationBounds::min_dihedral_degrees (Shewchuk 2002)                |
/// | pathologies   | each pathology's object and host exist; a myoma-intramural lies inside the  |
/// |               | host's tissue, every other kind outside it, nearest to the cavity wall      |
/// |               | (host vertex attribute "cavity" = 1, when the host has one)                 |
/// | attachments   | each pathology is connected to its host by ≥ 3 node pairs                   |
/// | connections   | every connection names two objects, valid nodes, ≥ 3 pairs, positive        |
/// |               | stiffness, and its paired nodes lie within max_connection_gap, or within    |
/// |               | the longest tet edge at either node when the bodies are coarser than that   |
/// | references    | vessel trees name an existing host, parents precede children, finite        |
/// |               | geometry and positive radii; landmarks name existing objects                |

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"

namespace viscera::templates {

/// The bounds the checks hold a patient to.
struct ValidationBounds {
  /// Smallest dihedral angle, degrees, allowed in any simulation tet. gmsh's Delaunay fill with
  /// the Netgen optimiser keeps hysteroscopy bodies above about 6°; below 2° the explicit step
  /// of the Teschner volume term shrinks by an order of magnitude.
  double min_dihedral_degrees = 2.0;
  /// Largest distance in m between the two nodes of a connection pair (seed 001 §3.3: joined at
  /// the nearest knots). A coarse body's nearest knot can lie further: a pair is also accepted
  /// within the longest tet edge that meets either of its nodes.
  double max_connection_gap = 0.004;
  /// m: a pathology vertex this close to the host's wall counts as on it, not in it.
  double wall_tolerance = 5e-4;
};

/// Outcome of one named check.
struct ValidationCheck {
  std::string name;  ///< "surfaces", "overlap", "tets", "pathologies", …
  bool passed = true;
  std::string detail;  ///< why it failed (one sentence naming the object), or empty
  nlohmann::json measures = nlohmann::json::object();  ///< e.g. {"min_dihedral_degrees": 7.2}
};

/// All checks of one patient, in a fixed order.
struct PatientValidation {
  std::vector<ValidationCheck> checks;

  bool valid() const;
  /// "check: detail" of the first failed check, or empty when valid.
  std::string first_failure() const;
  /// {"valid": bool, "checks": {name: {"passed", "detail"?, measures…}}}.
  nlohmann::json to_json() const;
};

/// Runs the geometric checks above on `scenario`. Never throws for a bad patient: every
/// problem is a failed check.
PatientValidation validate_patient_geometry(const core::Scenario& scenario,
                                            const ValidationBounds& bounds = {});

}  // namespace viscera::templates
