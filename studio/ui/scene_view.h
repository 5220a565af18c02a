#pragma once
/// The studio's 3D view (issue 9 §2–3): every scene object's visual surface as a VTK actor,
/// textured with its baked albedo map when the package has one, coloured by role otherwise.
/// A click without dragging picks the object under the cursor; the selected object gets a
/// bounding-box outline. Camera interaction is VTK's trackball, as in 3D Slicer and ParaView.
/// What is drawn and how opaque follows the document's view state (view_state.h) and nothing
/// else (issue 23 §4). A clipping plane cuts every object open to see inside an organ, and a
/// camera preset looks from the cervix into the uterine cavity (issue 23 §2).

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkPlane.h>
#include <vtkProp3D.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <QString>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "studio/document/scenario_document.h"
#include "studio/document/view_state.h"

namespace viscera::studio {

class SceneView : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit SceneView(QWidget* parent = nullptr);

  /// Rebuilds every actor from `scenario`, drawn as the view state in `files` says; keeps the
  /// selection of an id that remains. `frame` resets the camera to the whole scene.
  void show_scenario(const core::Scenario& scenario, const PackageFiles& files, bool frame);
  /// Shows, hides and fades the actors as `state` says (a view-state command).
  void apply_view_state(const ViewState& state);
  bool object_visible(const QString& id) const;
  /// Opacity of object `id`'s actor in [0, 1] (0 for an unknown id).
  double object_opacity(const QString& id) const;
  /// Whether vessel tree `tree_id` is drawn.
  bool vessel_tree_visible(const QString& tree_id) const;
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
  /// Cuts the organs, vessel objects and vessel trees with the plane through `origin` (m) with
  /// unit `normal` — the half-space the normal points into stays, the cut shows the wall's
  /// inside darker — while pathologies, fixtures and instruments stay whole, so the lesions
  /// inside an organ show in the open cavity.
  void set_clip_plane(const core::Vec3& origin, const core::Vec3& normal);
  /// The clipping plane across the objects' bounding box: perpendicular to `axis` (0 x
  /// left–right/sagittal, 1 y antero-posterior/coronal, 2 z axial) at `fraction` of the box
  /// from its low side; `keep_low` keeps the low side instead of the high.
  void set_clip_across(int axis, double fraction, bool keep_low);
  void set_clipping(bool on);
  bool clipping() const { return clipping_; }
  vtkPlane* clip_plane() const { return clip_plane_; }
  /// A hysteroscope's view: from the scenario's "cervix-internal-os" landmark along the canal
  /// into the cavity, towards the centre of the vertices marked "cavity" = 1 on the host's
  /// surface (else the "fundus" landmark), anterior up, 70° view angle. False, leaving the camera,
  /// when the scenario has no cervix landmarks.
  bool view_from_cervix(const core::Scenario& scenario);
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
  void update_clipping();

  vtkSmartPointer<vtkRenderer> renderer_;
  std::map<QString, vtkSmartPointer<vtkActor>> actors_;
  std::map<QString, vtkSmartPointer<vtkActor>> vessel_actors_;  ///< by vessel tree id
  std::set<QString> clipped_;  ///< organs and vessel objects: what the plane cuts
  vtkSmartPointer<vtkPlane> clip_plane_;
  bool clipping_ = false;
  vtkSmartPointer<vtkActor> outline_;
  std::vector<vtkSmartPointer<vtkProp3D>> image_planes_;
  QString selected_;
  QPoint press_position_;
};

}  // namespace viscera::studio
