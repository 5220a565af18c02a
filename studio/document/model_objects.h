#pragma once
/// Model objects in the studio (issue 9 §4; seed 001 §3.3): a scene object built from a
/// core::ModelDocument (a ball, flat or pipe shaped by control points) keeps its model as the
/// package file "models/<id>.viscera-model.json", so the studio can move its control points
/// after a save and reopen. Moving a point is `viscera model move-point` followed by
/// core::build_model_object, as one undoable command.

#include <QUndoCommand>
#include <optional>
#include <string>

#include "core/modelling/model_document.h"
#include "core/progress.h"
#include "studio/document/scenario_document.h"

namespace viscera::studio {

/// Package path of object `id`'s model.
std::string model_file_path(const std::string& object_id);
/// The model of object `id` in `files`, or nothing. Throws core::InputError for a stored model
/// that does not parse.
std::optional<core::ModelDocument> object_model(const PackageFiles& files,
                                                const std::string& object_id);
/// The model files of `scenario`'s objects present in the package at `path` (folder or .vscz).
PackageFiles read_package_models(const std::filesystem::path& path, const core::Scenario& scenario);

/// The scene object of `model` (core::build_model_object) with `fallback` as its material when
/// the model names none. Safe on a worker thread.
core::SceneObject build_studio_model_object(const core::ModelDocument& model,
                                            const std::string& fallback_material,
                                            core::Progress& progress = core::Progress::none());

/// Adds a model object: the object, its material when new, and its model file.
class AddModelObjectCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when the id is taken.
  AddModelObjectCommand(ScenarioDocument& document, core::ModelDocument model,
                        core::SceneObject object, std::optional<core::Material> material);
  void redo() override;
  void undo() override;

 private:
  ScenarioDocument& document_;
  core::SceneObject object_;
  std::string model_bytes_;
  std::optional<core::Material> material_;
};

/// Moves one control point of a model object: the model file and the rebuilt object replace the
/// old ones (material and texture stay the object's).
class MoveControlPointCommand : public QUndoCommand {
 public:
  /// `moved` is the model after core::move_model_control_point and `rebuilt` its object.
  /// Throws core::UsageError for an object without a model.
  MoveControlPointCommand(ScenarioDocument& document, const core::ModelDocument& moved,
                          core::SceneObject rebuilt, int index);
  void redo() override;
  void undo() override;

 private:
  void set(const core::SceneObject& object, const std::string& model_bytes);

  ScenarioDocument& document_;
  core::SceneObject old_object_, new_object_;
  std::string old_model_, new_model_;
};

}  // namespace viscera::studio
