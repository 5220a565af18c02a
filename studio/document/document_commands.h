#pragma once
/// The edits of the studio (issue 9 §1): each is a QUndoCommand on a ScenarioDocument, so the
/// document's undo stack can take back and redo every change a user makes.

#include <QUndoCommand>
#include <optional>
#include <string>

#include "core/scenario/scenario.h"
#include "studio/document/scenario_document.h"

namespace viscera::studio {

/// Adds a scene object, and its material when the scenario does not have one with that id.
class AddObjectCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when the id is taken.
  AddObjectCommand(ScenarioDocument& document, core::SceneObject object,
                   std::optional<core::Material> material = std::nullopt);
  void redo() override;
  void undo() override;

 private:
  ScenarioDocument& document_;
  core::SceneObject object_;
  std::optional<core::Material> added_material_;
};

/// Removes a scene object (it comes back in its place on undo).
class RemoveObjectCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError for an unknown id or an object a pathology or connection uses.
  RemoveObjectCommand(ScenarioDocument& document, const std::string& object_id);
  void redo() override;
  void undo() override;

 private:
  ScenarioDocument& document_;
  core::SceneObject object_;
  std::size_t index_ = 0;
};

/// Gives an object a material: `material` is added to the scenario when its id is new (a
/// library tissue), otherwise the scenario's material of that id is used unchanged.
class AssignMaterialCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError for an unknown object id.
  AssignMaterialCommand(ScenarioDocument& document, const std::string& object_id,
                        const core::Material& material);
  void redo() override;
  void undo() override;

 private:
  ScenarioDocument& document_;
  std::string object_id_;
  std::string old_material_;
  core::Material material_;
  bool adds_material_ = false;
};

/// The numeric material parameters the property panel edits.
enum class MaterialField {
  Density,            ///< kg/m³
  DistanceStiffness,  ///< Pa
  AreaStiffness,      ///< N/m
  VolumeStiffness,    ///< Pa
  DistanceDamping,    ///< Pa·s
  TearingThreshold,   ///< strain
  PlasticYield,       ///< strain
};
/// Human name with unit, e.g. "density (kg/m³)".
QString material_field_label(MaterialField field);
/// Reads / writes one field of a material.
double material_field(const core::Material& material, MaterialField field);
void set_material_field(core::Material& material, MaterialField field, double value);

/// Sets one parameter of a scenario material; successive edits of the same field of the same
/// material merge into one undo step (a spin box being dragged).
class EditMaterialCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError for an unknown material or a negative or non-finite value.
  EditMaterialCommand(ScenarioDocument& document, const std::string& material_id,
                      MaterialField field, double value);
  void redo() override;
  void undo() override;
  int id() const override { return 1; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  void apply(double value);

  ScenarioDocument& document_;
  std::string material_id_;
  MaterialField field_;
  double old_value_ = 0.0;
  double new_value_ = 0.0;
};

}  // namespace viscera::studio
