#pragma once
/// An organ's body re-meshed around a new hole in its wall: what placing an intramural myoma
/// from the studio does to its host, as the hysteroscopy template meshes the uterus around its
/// intramural myomas (seed 000 §1.1: a myoma inside the myometrium). What was authored on the
/// old body — wall layers, fixed knots, connections to its knots — is carried over to the new
/// one by position.

#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::studio {

/// The host rebuilt: its object with the new body (nodes, tets, boundary, masses, fixed flags,
/// layer labels) and its visual surface embedded in it, and the scenario's connections to the
/// host with their host knots moved to the new body (ids and stiffness kept).
struct RemeshedHost {
  core::SceneObject object;
  std::vector<core::Connection> connections;
};

/// Fills object `host_id`'s closed (welded) surface with gmsh tets around `holes` — closed,
/// outward surfaces inside its wall — and around the objects of the intramural pathologies it
/// already holds. Carried over from the old body by position:
/// - each new tet takes the layer label of the old tet holding its centroid;
/// - a new node is fixed when the corner nearest to it of the old tet holding it is fixed;
/// - each host knot of a connection moves to the new node nearest to it;
/// - a host with hydrometra pressure states gets them computed again for the new body
///   (simulator/dynamics/hydrometra_sweep.h).
/// Masses are lumped per tet with the density of the tet's layer material (the object's
/// material for unlisted labels; the old body's mean density when the scenario lacks it), kg.
/// The new body's first nodes are the welded surface's vertices, then each hole's.
/// Throws core::UsageError when the host is unknown or has no tet body; core::InputError when
/// gmsh refuses the region (a hole that crosses the wall or another hole); CancelledError.
RemeshedHost remesh_around_holes(const core::Scenario& scenario, const std::string& host_id,
                                 const std::vector<core::SurfaceMesh>& holes,
                                 core::Progress& progress = core::Progress::none());

}  // namespace viscera::studio
