#pragma once
/// The uterus of the hysteroscopy template (seed 000 §1.2, §2.1): one closed genus-0 surface
/// whose meridian runs from the top of the cavity down the cavity wall, through the cervical
/// canal, round the lip of the external os and up the outside to the fundus — so the wall, the
/// cavity and the canal are a single watertight solid ready for tetrahedral meshing. Cross
/// sections are ellipses: the cavity flat and wide (triangular in the coronal plane, widest at
/// the cornua), the canal round and spindle-shaped. Funnel-shaped tubal orifices are pressed
/// into the cornua, the body is bent forward (anteflexion) and finally carried through a smooth
/// random deformation field. Coordinates: z from the external os (z = 0) towards the fundus,
/// x to the patient's left, y anterior. Lengths in m, angles in rad.

#include <string>
#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/scenario/scenario_parts.h"
#include "templates/variability/smooth_deformation.h"

namespace viscera::templates {

/// Dimensions of the uterus.
struct UterusDimensions {
  double length = 0.075;          ///< external os to the top of the fundus
  double width = 0.05;            ///< largest outer width (left–right)
  double thickness = 0.035;       ///< largest outer thickness (antero-posterior)
  double cervix_length = 0.025;   ///< cervical canal, external to internal os
  double cervix_radius = 0.013;   ///< outer radius of the cervix
  double canal_radius = 0.0025;   ///< lumen of the cervical canal (distended)
  double cavity_length = 0.035;   ///< internal os to the top of the cavity
  double cavity_width = 0.03;     ///< between the cornua
  double cavity_depth = 0.012;    ///< antero-posterior opening of the distended cavity
  double orifice_radius = 0.005;  ///< funnel of a tubal orifice
  double orifice_depth = 0.0025;  ///< how far the funnel reaches into the wall
  double flexion = 0.3;           ///< anteflexion of the body against the cervix, rad
  double edge_length =
      0.005;  ///< target triangle edge on the outside; the cavity gets 0.7×, the canal 0.5×
};

/// The generated surface and what the template needs to know about it.
struct UterusShape {
  core::SurfaceMesh surface;              ///< the wall: closed, outward, cavity and canal included
  core::SurfaceMesh envelope;             ///< the outer skin closed by a disc over the external os
  std::vector<std::uint8_t> cavity;       ///< per surface vertex: 1 cavity wall, 2 canal, 0 outside
  std::vector<core::Landmark> landmarks;  ///< tubal orifices, internal and external os, fundus
  double internal_os_height = 0.0;        ///< z of the internal os before bending, m
};

/// Throws core::UsageError naming the dimension when the dimensions contradict each other (a
/// wall thinner than 4 mm anywhere, a canal wider than the cervix, …).
void check_uterus_dimensions(const UterusDimensions& d);

/// Builds the uterus, then maps it through `deformation`. Throws as check_uterus_dimensions.
UterusShape make_uterus(const UterusDimensions& d, const SmoothDeformation& deformation);

}  // namespace viscera::templates
