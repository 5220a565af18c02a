#pragma once
/// The display dock (issue 23 §2, seeing inside an organ): the selected object's opacity (an
/// undoable view-state change, view_state.h), a clipping plane across the scene that cuts the
/// organs open (pathologies stay whole; SceneView::set_clip_plane) — sagittal, coronal or
/// axial, moved with a slider or with the image volume's slice of its orientation, either side
/// kept — and the camera presets (the whole scene; from the cervix into the uterine cavity, as a
/// hysteroscope sees it). Every control is also a public function for tests.

#include <QWidget>

#include "core/math_types.h"
#include "studio/document/scenario_document.h"

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QSlider;

namespace viscera::studio {

class SceneView;

class DisplayPanel : public QWidget {
  Q_OBJECT

 public:
  DisplayPanel(ScenarioDocument& document, SceneView& view, QWidget* parent = nullptr);

  /// The selected object (empty: none; the opacity slider is disabled).
  void show_object(const QString& id);
  /// Follows a view-state change (undo, redo, opening).
  void refresh();

  /// Turns the clipping plane on or off and places it: `axis` 0 sagittal (x), 1 coronal (y),
  /// 2 axial (z); `fraction` of the scene's extent along it; `keep_low` keeps the low side.
  void set_clipping(bool on, int axis = 1, double fraction = 0.5, bool keep_low = false);
  /// Whether the plane follows the image volume's slice of its axis ("With the slices").
  bool follows_slices() const;
  void set_follows_slices(bool on);
  /// The plane's axis: 0 sagittal, 1 coronal, 2 axial.
  int clip_axis() const;
  /// With the slices: puts the plane through world point `on_slice` (m) of the slice of the
  /// plane's axis; nothing when not following or clipping is off.
  void follow_slice(const core::Vec3& on_slice);
  /// Looks from the cervix into the cavity; false (after failed()) without cervix landmarks.
  bool view_from_cervix();

  QSlider* opacity_slider() const { return opacity_; }
  QSlider* clip_slider() const { return clip_position_; }

 signals:
  /// The user moved the opacity slider of object `id` to `opacity` in [0, 1].
  void opacity_requested(const QString& id, double opacity);
  void failed(const QString& message);
  /// Following the slices: the plane wants the current slice's position (follow_slice()).
  void slice_plane_requested();

 private:
  void update_clip();

  ScenarioDocument& document_;
  SceneView& view_;
  QString object_id_;
  bool updating_ = false;
  QLabel* object_label_ = nullptr;
  QSlider* opacity_ = nullptr;
  QGroupBox* clip_box_ = nullptr;
  QComboBox* clip_axis_ = nullptr;
  QSlider* clip_position_ = nullptr;
  QCheckBox* clip_flip_ = nullptr;
  QCheckBox* follow_slices_ = nullptr;
};

}  // namespace viscera::studio
