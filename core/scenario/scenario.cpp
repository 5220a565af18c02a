#include "core/scenario/scenario.h"

#include "core/error.h"

namespace viscera::core {

std::string to_string(ObjectRole role) {
  switch (role) {
    case ObjectRole::Organ:
      return "organ";
    case ObjectRole::Pathology:
      return "pathology";
    case ObjectRole::Vessel:
      return "vessel";
    case ObjectRole::Fixture:
      return "fixture";
    case ObjectRole::Instrument:
      return "instrument";
  }
  return "organ";
}

std::string to_string(BodyKind kind) {
  switch (kind) {
    case BodyKind::None:
      return "none";
    case BodyKind::TetMesh:
      return "tet-mesh";
    case BodyKind::MassSpring:
      return "mass-spring";
    case BodyKind::CellAgent:
      return "cell-agent";
    case BodyKind::UrethraLattice:
      return "urethra-lattice";
  }
  return "none";
}

ObjectRole object_role_from_string(const std::string& name) {
  for (const auto role : {ObjectRole::Organ, ObjectRole::Pathology, ObjectRole::Vessel,
                          ObjectRole::Fixture, ObjectRole::Instrument}) {
    if (to_string(role) == name) return role;
  }
  throw InputError("unknown object role \"" + name + "\"");
}

BodyKind body_kind_from_string(const std::string& name) {
  for (const auto kind : {BodyKind::None, BodyKind::TetMesh, BodyKind::MassSpring,
                          BodyKind::CellAgent, BodyKind::UrethraLattice}) {
    if (to_string(kind) == name) return kind;
  }
  throw InputError("unknown body kind \"" + name + "\"");
}

const SceneObject* Scenario::find_object(const std::string& id) const {
  for (const auto& object : objects) {
    if (object.id == id) return &object;
  }
  return nullptr;
}

}  // namespace viscera::core
