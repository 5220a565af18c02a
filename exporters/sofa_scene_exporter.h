#pragma once
/// A SOFA scene (.scn XML) of a scenario that behaves like the Viscera patient, written for
/// SOFA v26.06 (the release named in the scene's header comment, "sofa-version v26.06"). Open it
/// with `runSofa X.scn`. Component semantics are taken from SOFA's source (sofa-framework/sofa):
///   RequiredPlugin.cpp            plugins are named by `pluginName` (`name` is only a fallback)
///   EulerImplicitSolver.cpp       rayleighStiffness/rayleighMass enter matrix and right-hand side
///   CGLinearSolver.inl            stops on |r|/|b| ≤ tolerance or pᵀAp ≤ threshold
///   MeshSpringForceField.inl      one spring per edge, stiffness S / rest length
///   SpringForceField.inl          f = (ks (l − L) + kd l̇) u, implicit stiffness ∂f/∂x
///   BaseLinearElasticityFEMForceField.inl  youngModulus/poissonRatio: one value or one per tet
///   BarycentricPenalityContact.inl, PenalityContactForceField.inl  k = k₁ k₂ / d0 per contact
///   DefaultAnimationLoop.cpp      part of Sofa.Simulation.Core: no plugin to require
///
/// The root holds the session's step and gravity, the plugins of the components written, the
/// collision pipeline when the session has contact (CollisionPipeline, BruteForceBroadPhase,
/// BVHNarrowPhase, MinProximityIntersection, CollisionResponse with PenalityContactForceField),
/// one EulerImplicitSolver with the bodies' Rayleigh β and one CGLinearSolver whose settings
/// converge for the scene's masses and step (sofa_solver_settings.h). Per object with a body, a
/// node "<id>" with:
///   MeshVTKLoader      <X>_meshes/<id>_body.vtk (legacy 4.2 ASCII: points and tetrahedra only)
///   MeshTopology, MechanicalObject "dofs"
///   DiagonalMass       massDensity, or the package's vertexMass when the node masses are not the
///                      lumped density·volume/4
///   TetrahedronFEMForceField (tet bodies, corotational "large"), E and ν per tet for layered
///                      walls; or the KisMo edge springs (sofa_material.h): MeshSpringForceField
///                      tetrahedraStiffness when one value gives every edge its constant, else a
///                      SpringForceField listing each edge's spring
///   FixedProjectiveConstraint on the held nodes (never on attached nodes, sofa_body.h)
///   a child "collision" (with contact): the boundary as a point set mapped by SubsetMapping,
///                      Triangle/Line/PointCollisionModel with contactStiffness √(k_V d0)
///   a child "visual": MeshOBJLoader <X>_meshes/<id>_surface.obj, OglModel with the baked albedo,
///                      BarycentricMapping from the body (SOFA's twin of our embedding)
/// Objects without a body become static visual models. Each connection between two exported
/// bodies becomes a SpringForceField between their "dofs", one spring per node pair (stiffness
/// N/m, rest length = the pair's distance): that is how a pathology is attached to its host
/// wall, its attached nodes free. Urethra lattices and cell-agent tissue are refused
/// (sofa_body.h).

#include <filesystem>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "exporters/export_object.h"

namespace viscera::exporters {

/// The SOFA release the scene is written for.
inline constexpr const char* kSofaRelease = "v26.06";

/// The scene XML; mesh and map paths are "<folder>/…" relative to the scene file. Throws
/// core::UsageError for objects SOFA cannot simulate (sofa_body.h).
std::string sofa_scene_xml(const core::Scenario& scenario, const std::vector<ExportObject>& objects,
                           const std::string& folder);

}  // namespace viscera::exporters
