#pragma once
/// Undoable edits of the organ panels (issue 9 §5): a baked texture assigned to an object, a
/// vessel tree added to an organ, a pathology placed on an organ wall. Each is one QUndoCommand
/// holding what it adds and what it replaces, computed beforehand (organ_authoring.h).

#include <QUndoCommand>
#include <optional>
#include <string>

#include "studio/document/organ_authoring.h"
#include "studio/document/scenario_document.h"

namespace viscera::studio {

/// Gives an object a baked texture: the spec enters Scenario::textures, the object (with its
/// possibly re-cut surface and UVs) replaces the old one and the maps enter the package files.
class ApplyTextureCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when the scenario has no object of that id.
  ApplyTextureCommand(ScenarioDocument& document, TexturedObject textured);
  void redo() override;
  void undo() override;

 private:
  ScenarioDocument& document_;
  TexturedObject new_;
  core::SceneObject old_object_;
  std::optional<core::TextureSpec> old_spec_;
  std::map<std::string, std::optional<std::string>> old_files_;
};

/// Adds a vessel tree (removed again on undo).
class AddVesselTreeCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when the id is taken or the host is unknown.
  AddVesselTreeCommand(ScenarioDocument& document, core::VesselTree tree);
  void redo() override;
  void undo() override;

 private:
  ScenarioDocument& document_;
  core::VesselTree tree_;
};

/// Adds a pathology: its object, its material when new, its record and its connection; for an
/// intramural myoma it also swaps in the re-meshed host and its moved connections (undo puts
/// the old host and connections back).
class AddPathologyCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when the object or pathology id is taken, or when a re-meshed
  /// host or one of its connections is not in the scenario.
  AddPathologyCommand(ScenarioDocument& document, PathologyParts parts);
  void redo() override;
  void undo() override;

 private:
  /// Puts `object` and `connections` in place of the scenario's ones with the same ids.
  void swap_host(const core::SceneObject& object, const std::vector<core::Connection>& connections);

  ScenarioDocument& document_;
  PathologyParts parts_;
  std::optional<RemeshedHost> old_host_;
};

/// Replaces a scenario material as a whole (a stress–strain fit changes its curve and its
/// derived constants together); undo restores the old one.
class ReplaceMaterialCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when the scenario has no material with `material.id`.
  ReplaceMaterialCommand(ScenarioDocument& document, core::Material material);
  void redo() override;
  void undo() override;

 private:
  void set(const core::Material& material);

  ScenarioDocument& document_;
  core::Material old_, new_;
};

/// Adds an active deformation (pulse or motility), or replaces the one with the same id.
class SetActiveDeformationCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when its target object is unknown.
  SetActiveDeformationCommand(ScenarioDocument& document, core::ActiveDeformation deformation);
  void redo() override;
  void undo() override;

 private:
  void set(const std::optional<core::ActiveDeformation>& deformation);

  ScenarioDocument& document_;
  core::ActiveDeformation new_;
  std::optional<core::ActiveDeformation> old_;
};

}  // namespace viscera::studio
