#pragma once
/// The pathology panel (issue 9 §5; seed 000 §1.1, §12): choose a kind (polyp, sessile or
/// pedunculated myoma) and a size, arm "Place by clicking", and a click on an organ's surface in
/// the 3D view seats the pathology there — shaped, meshed and attached as the hysteroscopy
/// template does (templates::shape_pathology_at, add_tet_object, attach) — as one undoable
/// command adding its object, its Scenario::pathologies entry and its connection to the organ.

#include "core/math_types.h"
#include "studio/ui/organ_panel.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace viscera::studio {

class PathologyPanel : public OrganPanel {
  Q_OBJECT

 public:
  explicit PathologyPanel(ScenarioDocument& document, QWidget* parent = nullptr);

  /// Places a pathology of `kind` and `size` m on the wall of object `host` nearest to `point`
  /// (m) and returns the new pathology's id, or empty (after failed()) when it does not fit.
  QString place_pathology_on(const QString& host, const core::Vec3& point, const QString& kind,
                             double size);
  /// The same on the shown object.
  QString place_pathology_at(const core::Vec3& point, const QString& kind, double size);
  /// Sets the editors: kind ("polyp", "myoma-submucosal", "myoma-pedunculated"), size in m.
  void set_choice(const QString& kind, double size);
  /// Whether the next click on an organ places a pathology (the "Place by clicking" button).
  bool armed() const;
  void set_armed(bool armed);
  /// The 3D view's click: places what the editors show when armed and `id` is an organ.
  void on_surface_clicked(const QString& id, const core::Vec3& point);

 signals:
  /// A pathology was placed (its id), e.g. to select it.
  void placed(const QString& id);

 private:
  void refresh() override;

  QLabel* object_label_ = nullptr;
  QComboBox* kind_ = nullptr;
  QDoubleSpinBox* size_mm_ = nullptr;
  QSpinBox* seed_ = nullptr;
  QPushButton* arm_ = nullptr;
};

}  // namespace viscera::studio
