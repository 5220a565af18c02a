#pragma once
/// Three orthogonal slice views of an image volume (issue 9 §2; seed 001 §3.3: the image volume
/// as a modelling aid), as in 3D Slicer: axial (k), coronal (j) and sagittal (i) index planes,
/// each with a slider, one window/level shared by all three with CT and MR presets, and the
/// three planes also placed in the 3D view at their world positions (origin, spacing and
/// direction of core::ImageVolume, applied as the slices' user matrix).

#include <vtkImageData.h>
#include <vtkImageProperty.h>
#include <vtkImageSlice.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <QPoint>
#include <QWidget>
#include <array>
#include <optional>

#include "core/image/image_volume.h"

class QDoubleSpinBox;
class QSlider;
class QVTKOpenGLNativeWidget;
class vtkMatrix4x4;
class vtkRenderer;

namespace viscera::studio {

/// Window/level presets (Hounsfield units for CT; MR relative to the volume's range).
struct WindowLevelPreset {
  const char* name;
  double window;
  double level;
};
/// "CT soft tissue" (400/40), "CT bone" (2000/400), "CT lung" (1500/-600).
const std::array<WindowLevelPreset, 3>& ct_window_presets();

class SliceViews : public QWidget {
  Q_OBJECT

 public:
  explicit SliceViews(QWidget* parent = nullptr);

  /// Shows `volume`: slices at the middle, window/level over its full value range.
  void set_volume(const core::ImageVolume& volume);
  bool has_volume() const { return image_ != nullptr; }
  const std::array<int, 3>& dims() const { return dims_; }

  /// Axis 0 = sagittal (i), 1 = coronal (j), 2 = axial (k). Clamped to the volume.
  void set_slice(int axis, int index);
  int slice(int axis) const;
  void set_window_level(double window, double level);
  double window() const;
  double level() const;

  /// The plane of `axis` as a prop for the 3D view (shares image and window/level).
  vtkImageSlice* plane_in_3d(int axis) const { return planes_3d_[axis]; }
  /// The rendered slice view of `axis`.
  QImage grab_view(int axis);
  /// The view widget and renderer of `axis` (overlays add their props there).
  QVTKOpenGLNativeWidget* view(int axis) const { return views_[axis]; }
  vtkRenderer* renderer(int axis) const { return renderers_[axis]; }
  /// Renders the three views again (after an overlay changed).
  void render_all();

  /// The world point (m) on the shown slice of `axis` under widget pixel `position` (logical
  /// coordinates) of its view; none without a volume.
  std::optional<core::Vec3> world_at(int axis, const QPoint& position) const;
  /// The widget pixel (logical) of the view of `axis` where world point `point` (m) is drawn.
  QPoint position_of(int axis, const core::Vec3& point) const;

 signals:
  /// A slice moved or window/level changed: the 3D view should render again.
  void changed();
  /// A left click (press and release without dragging) at world point `point` (m) on the slice
  /// of `axis`.
  void point_clicked(int axis, const viscera::core::Vec3& point);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  vtkSmartPointer<vtkImageData> image_;
  vtkSmartPointer<vtkMatrix4x4> matrix_;
  vtkSmartPointer<vtkImageProperty> property_;
  std::array<int, 3> dims_{0, 0, 0};
  std::array<QVTKOpenGLNativeWidget*, 3> views_{};
  std::array<vtkSmartPointer<vtkRenderer>, 3> renderers_{};
  std::array<vtkSmartPointer<vtkImageSlice>, 3> slices_{};
  std::array<vtkSmartPointer<vtkImageSlice>, 3> planes_3d_{};
  std::array<QSlider*, 3> sliders_{};
  QDoubleSpinBox* window_box_ = nullptr;
  QDoubleSpinBox* level_box_ = nullptr;
  bool updating_ = false;
  QPoint press_position_;
};

}  // namespace viscera::studio
