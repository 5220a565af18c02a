#pragma once
/// Which vessels of a patient's authored trees a cut opens, and how freely each bleeds (issue 18
/// §3; seed 000 §6.2: "the emission rate … in correlation with the intensity of bleeding defined
/// by local physiology"; seed 001 §5.1.2: "after a cut into a vessel, the corresponding object
/// knots are registered"). The seeds give no rate model. This one is Hagen–Poiseuille along the
/// tree: the opened vessel is reached from the tree's root through its ancestors, so
///
///   G = 1 / (R_feed + Σ_ancestors 8 μ L_a / (π r_a⁴) + 8 μ s L / (π r⁴)),
///
/// with s the fraction of the cut segment upstream of the cut and R_feed the resistance of the
/// vessel that feeds the authored tree, taken as one more root segment (the authored tree starts
/// inside the organ; without it a cut at the root would bleed without bound). The blood pressure
/// behind the opening is the arterial or venous pressure of the tree's kind. A deeper, thinner
/// vessel bleeds less: radius and level in the tree set the rate.
/// A segment is opened where the cut's faces cross its axis (a vessel in solid tissue) or, when
/// none does, where they ring its lumen within 1.5 radii of the axis (a hollow vessel body cut
/// across, whose wall is all the tissue there is).

#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/scenario/scenario_parts.h"

namespace viscera::sim::fluid {

/// Blood constants of the bleeding model (stated decisions; the seeds give none).
struct BleedingPhysiology {
  double blood_viscosity = 3.5e-3;     ///< Pa·s, whole blood at the shear rates of a cut vessel
  double arterial_pressure = 11300.0;  ///< Pa, 85 mmHg: mean pressure at an arterial tree's root
  double venous_pressure = 1300.0;     ///< Pa, 10 mmHg: the uterine venous plexus
  double capillary_pressure = 3300.0;  ///< Pa, 25 mmHg
  /// m³ s⁻¹ Pa⁻¹ per m² of fresh cut surface without a named vessel: 0.3 ml/min per cm² into an
  /// empty cavity at the capillary pressure.
  double capillary_conductance = 0.3e-6 / 60.0 / 1e-4 / 3300.0;
  double ooze_time_constant = 60.0;  ///< s, e-folding time of capillary ooze as it clots
};

/// A vessel segment a cut crosses.
struct OpenedVessel {
  int segment = 0;           ///< index into the tree's segments
  int triangle = 0;          ///< the cut triangle its axis crosses (index into the given list)
  core::Vec3 barycentric;    ///< of the crossing in that triangle
  core::Vec3 site;           ///< m, the crossing in the body's rest frame
  double along = 0.0;        ///< where the crossing lies on the segment: 0 proximal … 1 distal
  double radius = 0.0;       ///< m
  int level = 0;             ///< bifurcations between the tree's root and the segment
  std::vector<int> path;     ///< segments from the root to this one, both included
  double conductance = 0.0;  ///< m³ s⁻¹ Pa⁻¹, Poiseuille along the path (above)
  double pressure = 0.0;     ///< Pa, the blood pressure behind the opening
};

/// The segments of `tree` whose axis crosses one of `triangles` (vertex indices into `nodes`,
/// positions in m in the frame the tree was authored in: the host body's rest frame), one entry
/// per segment at its crossing nearest the proximal end, in segment order. Throws
/// core::InputError naming the tree and segment for a parent out of range or a cycle.
std::vector<OpenedVessel> find_opened_vessels(const core::VesselTree& tree,
                                              std::span<const core::Vec3> nodes,
                                              std::span<const core::Triangle> triangles,
                                              const BleedingPhysiology& physiology = {});

/// m², total area of `triangles` over `nodes`.
double triangles_area(std::span<const core::Vec3> nodes, std::span<const core::Triangle> triangles);

}  // namespace viscera::sim::fluid
