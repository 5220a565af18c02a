#pragma once
/// The studio's 3D view (issue 9 §2–3): every scene object's visual surface as a VTK actor,
/// textured with its baked albedo map when the package has one, coloured by role otherwise.
/// A click without dragging picks the object under the cursor; the selected object gets a
/// bounding-box outline. Camera interaction is VTK's trackball, as in 3D Slicer and ParaView.

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkProp3D.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <QString>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "studio/document/scenario_document.h"

namespace viscera::studio {

class SceneView : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit SceneView(QWidget* parent = nullptr);

  /// Rebuilds every actor from `scenario`; keeps visibility and selection of ids that remain.
  /// `frame` resets the camera to the whole scene.
  void show_scenario(const core::Scenario& scenario, const PackageFiles& files, bool frame);
  void set_object_visible(const QString& id, bool visible);
  bool object_visible(const QString& id) const;
  /// Selects (outlines) an object; an empty id clears the selection.
  void select_object(const QString& id);
  QString selected_object() const { return selected_; }
  /// The object drawn at widget pixel `position` (logical coordinates), or an empty string.
  QString object_at(const QPoint& position);
  /// The object surface drawn at widget pixel `position` and the world point (m) hit there.
  std::optional<std::pair<QString, core::Vec3>> surface_point_at(const QPoint& position);
  /// Number of vessel trees drawn (as tubes of their segments' radii).
  int vessel_tree_count() const { return static_cast<int>(vessel_actors_.size()); }
  /// The actor of object `id`, or null (tests, the organ panels' previews).
  vtkActor* object_actor(const QString& id) const;
  /// Shows these props (the image volume's slice planes) with the objects; not pickable.
  void set_image_planes(const std::vector<vtkProp3D*>& planes);
  /// Frames the whole scene from the front-right, above, with +z up.
  void reset_camera();
  void render();
  /// Number of objects drawn with a texture map.
  int textured_object_count() const;
  vtkRenderer* renderer() const { return renderer_; }

 signals:
  /// The user clicked on an object (empty id: on the background).
  void object_picked(const QString& id);
  /// The same click, with the world point (m) on the object's surface.
  void surface_clicked(const QString& id, const viscera::core::Vec3& point);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  void update_outline();

  vtkSmartPointer<vtkRenderer> renderer_;
  std::map<QString, vtkSmartPointer<vtkActor>> actors_;
  std::map<QString, bool> hidden_;
  std::vector<vtkSmartPointer<vtkActor>> vessel_actors_;
  vtkSmartPointer<vtkActor> outline_;
  std::vector<vtkSmartPointer<vtkProp3D>> image_planes_;
  QString selected_;
  QPoint press_position_;
};

}  // namespace viscera::studio
