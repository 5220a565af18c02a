#pragma once
/// A SOFA scene (.scn XML) of a scenario, for SOFA ≥ v24.06 (component names of the
/// Sofa.Component.* modules; earlier releases call FixedProjectiveConstraint FixedConstraint).
///
/// The root holds the time step and gravity of the session and one implicit Euler solver with a
/// conjugate-gradient linear solver for every body, so that connections couple bodies in one
/// system. Per object with a body, a node "<id>" with:
///   MeshVTKLoader      <X>_meshes/<id>_body.vtk (legacy 4.2 ASCII: points and tetrahedra only)
///   MeshTopology, MechanicalObject "dofs"
///   DiagonalMass       massDensity = material density, or the package's vertexMass when its
///                      node masses are not the lumped density·volume/4
///   TetrahedronFEMForceField (tet bodies, corotational "large") with E, ν and Rayleigh damping
///                      of sofa_material.h, or MeshSpringForceField (mass-spring bodies) with its
///                      mean edge stiffness and damping
///   FixedProjectiveConstraint on the package's fixed nodes
///   a child "visual": MeshOBJLoader <X>_meshes/<id>_surface.obj, OglModel with the baked albedo,
///                      BarycentricMapping from the body (SOFA's twin of our embedding)
/// Objects without a body (fixtures) become static visual models. Each connection between two
/// exported bodies becomes a SpringForceField between their "dofs" with one spring per node
/// pair (stiffness N/m, rest length = the pair's distance). Cell-agent tissue has no SOFA twin
/// and exports as visual only.

#include <filesystem>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "exporters/export_object.h"

namespace viscera::exporters {

/// The scene XML; mesh and map paths are "<folder>/…" relative to the scene file.
std::string sofa_scene_xml(const core::Scenario& scenario, const std::vector<ExportObject>& objects,
                           const std::string& folder);

}  // namespace viscera::exporters
