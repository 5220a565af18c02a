#pragma once
/// One object of a scene: an organ, pathology, vessel, fixture or instrument (DESIGN.md §3).

#include <map>
#include <string>

#include "core/mesh/surface_embedding.h"
#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "core/scenario/hydrometra_states.h"

namespace viscera::core {

/// What an object is to the clinician and the simulator.
enum class ObjectRole { Organ, Pathology, Vessel, Fixture, Instrument };
/// How an object is simulated.
enum class BodyKind { None, TetMesh, MassSpring, CellAgent, UrethraLattice };

std::string to_string(ObjectRole role);
std::string to_string(BodyKind kind);
/// Parse the names written by to_string; throw InputError on anything else.
ObjectRole object_role_from_string(const std::string& name);
BodyKind body_kind_from_string(const std::string& name);

/// A scene object with its meshes held in memory. In a package the meshes live in
/// objects/<id>/surface.vtp and objects/<id>/body.vtu (DESIGN.md §4).
struct SceneObject {
  std::string id;  ///< unique within the scenario; [a-z0-9_-]+
  std::string name;
  ObjectRole role = ObjectRole::Organ;
  std::string material;  ///< id in Scenario::materials, or empty
  std::string texture;   ///< id in Scenario::textures, or empty
  std::string group;     ///< organ group name, or empty
  BodyKind body_kind = BodyKind::None;
  SurfaceMesh surface;
  TetMesh body;                ///< nodes, tets, masses and fixed flags when body_kind is TetMesh
  SurfaceEmbedding embedding;  ///< surface vertices in body tets
  /// Material of the tets carrying each tet label (wall layers, e.g. 1 endometrium,
  /// 2 myometrium); tets whose label is not listed use `material`.
  std::map<int, std::string> layer_materials;
  /// The cavity's pre-computed pressure states (seed 000 §2.1), or empty: objects/<id>/
  /// hydrometra.bin in a package. Filled by the authoring pipeline for an organ whose surface
  /// marks a "cavity" (simulator/dynamics/hydrometra_sweep.h).
  HydrometraStates hydrometra;

  bool operator==(const SceneObject&) const = default;
};

}  // namespace viscera::core
