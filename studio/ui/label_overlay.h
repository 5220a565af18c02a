#pragma once
/// A label map drawn over the image volume (issue 9 §2): each label a semi-transparent colour
/// (vtkImageMapToColors through an indexed lookup table, label 0 fully transparent) in the
/// three slice views on the shown slices, and optionally as planes in the 3D view. The map
/// must share the volume's grid (studio::Segmentation checks it).

#include <vtkImageMapToColors.h>
#include <vtkImageSlice.h>
#include <vtkLookupTable.h>
#include <vtkSmartPointer.h>

#include <QObject>
#include <array>

#include "core/image/image_volume.h"

namespace viscera::studio {

class SliceViews;
class SceneView;

/// RGB of label `label` (1 red, 2 green, 3 blue, 4 yellow, … cycling through 12 colours).
std::array<double, 3> label_colour(int label);

class LabelOverlay : public QObject {
  Q_OBJECT

 public:
  LabelOverlay(SliceViews* slices, SceneView* view, QObject* parent = nullptr);

  /// Shows `labels` (an empty map hides the overlay).
  void set_labels(const core::LabelMap& labels);
  /// Opacity of labelled voxels in [0, 1] (default 0.5).
  void set_opacity(double opacity);
  double opacity() const { return opacity_; }
  /// Shows the overlay planes in the 3D view too.
  void set_shown_in_3d(bool shown);
  bool shown_in_3d() const { return shown_in_3d_; }

 private:
  /// Follows the slice views' slice numbers and renders.
  void sync();

  SliceViews* slices_;
  SceneView* view_;
  vtkSmartPointer<vtkImageData> image_;
  vtkSmartPointer<vtkLookupTable> table_;
  vtkSmartPointer<vtkImageMapToColors> colours_;
  std::array<vtkSmartPointer<vtkImageSlice>, 3> overlays_{};
  std::array<vtkSmartPointer<vtkImageSlice>, 3> overlays_3d_{};
  double opacity_ = 0.5;
  bool shown_in_3d_ = false;
  bool shown_ = false;
  bool syncing_ = false;
};

}  // namespace viscera::studio
