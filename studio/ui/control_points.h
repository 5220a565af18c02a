#pragma once
/// Draggable control points (issue 9 §4; seed 001 §3.3, KisMo's spline modelling): for the
/// selected model object (model_objects.h: balls, flats and pipes shaped by control points) a
/// vtkHandleWidget with a sphere per control point in the 3D view. Releasing a drag moves that
/// point (core::move_model_control_point, as `viscera model move-point`) and rebuilds the object
/// (core::build_model_object) as one undoable command. The panel also imports a model JSON
/// ("viscera-model", as `viscera model create` writes) as a new object.

#include <vtkHandleWidget.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <vector>

#include "core/math_types.h"
#include "core/modelling/model_document.h"
#include "studio/ui/organ_panel.h"

class QLabel;
class QPushButton;
class vtkObject;

namespace viscera::studio {

class SceneView;

class ControlPointPanel : public OrganPanel {
  Q_OBJECT

 public:
  ControlPointPanel(ScenarioDocument& document, SceneView& view, QWidget* parent = nullptr);
  ~ControlPointPanel() override;

  /// Builds `model`'s object off the UI thread and adds it (one command); returns its id, or
  /// empty after failed().
  QString add_model(const core::ModelDocument& model);
  /// Reads a model JSON and adds it.
  QString import_model(const std::filesystem::path& path);
  /// Moves control point `index` of the shown model object to `position` (m) and rebuilds it:
  /// what releasing a drag does. False after failed() for no model object or a bad index.
  bool move_control_point(int index, const core::Vec3& position);

  /// One handle per control point of the shown model object (none for other objects).
  int handle_count() const { return static_cast<int>(handles_.size()); }
  vtkHandleWidget* handle(int index) const { return handles_.at(static_cast<std::size_t>(index)); }
  /// World position of handle `index` as drawn.
  core::Vec3 handle_position(int index) const;

 signals:
  /// A model object was added (its id), e.g. to select it.
  void created(const QString& id);

 private:
  void refresh() override;
  void clear_handles();
  void on_interaction_end(vtkObject* caller);

  SceneView& view_;
  QLabel* label_ = nullptr;
  std::vector<vtkSmartPointer<vtkHandleWidget>> handles_;
  std::vector<core::Vec3> points_;  ///< the model's control points the handles started from
  std::string handles_for_;         ///< object id and model bytes the handles show
};

}  // namespace viscera::studio
