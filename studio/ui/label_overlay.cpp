#include "studio/ui/label_overlay.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageProperty.h>
#include <vtkImageSliceMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

#include <algorithm>

#include "core/image/image_volume_io.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/slice_views.h"

namespace viscera::studio {

std::array<double, 3> label_colour(int label) {
  static const std::array<std::array<double, 3>, 12> colours = {{
      {0.90, 0.10, 0.10},
      {0.10, 0.80, 0.20},
      {0.15, 0.35, 0.95},
      {0.95, 0.85, 0.10},
      {0.90, 0.20, 0.90},
      {0.10, 0.85, 0.85},
      {0.95, 0.55, 0.10},
      {0.55, 0.30, 0.85},
      {0.55, 0.85, 0.25},
      {0.85, 0.45, 0.55},
      {0.35, 0.60, 0.70},
      {0.70, 0.60, 0.35},
  }};
  return colours[static_cast<std::size_t>((std::max(label, 1) - 1) % 12)];
}

namespace {

vtkSmartPointer<vtkImageSlice> overlay_slice(int axis, vtkAlgorithmOutput* input) {
  auto mapper = vtkSmartPointer<vtkImageSliceMapper>::New();
  mapper->SetOrientation(axis);
  mapper->SetInputConnection(input);
  auto slice = vtkSmartPointer<vtkImageSlice>::New();
  slice->SetMapper(mapper);
  // The colours are final RGBA: no window/level, nearest voxels (labels do not blend).
  slice->GetProperty()->SetColorWindow(255.0);
  slice->GetProperty()->SetColorLevel(127.5);
  slice->GetProperty()->SetInterpolationTypeToNearest();
  slice->SetPickable(false);
  slice->SetVisibility(false);
  return slice;
}

}  // namespace

LabelOverlay::LabelOverlay(SliceViews* slices, SceneView* view, QObject* parent)
    : QObject(parent), slices_(slices), view_(view) {
  table_ = vtkSmartPointer<vtkLookupTable>::New();
  colours_ = vtkSmartPointer<vtkImageMapToColors>::New();
  colours_->SetLookupTable(table_);
  colours_->SetOutputFormatToRGBA();
  for (int axis = 0; axis < 3; ++axis) {
    overlays_[axis] = overlay_slice(axis, colours_->GetOutputPort());
    overlays_3d_[axis] = overlay_slice(axis, colours_->GetOutputPort());
    slices_->renderer(axis)->AddViewProp(overlays_[axis]);
    view_->renderer()->AddViewProp(overlays_3d_[axis]);
  }
  connect(slices_, &SliceViews::changed, this, &LabelOverlay::sync);
}

void LabelOverlay::set_labels(const core::LabelMap& labels) {
  int highest = 0;
  for (std::size_t v = 0; v < labels.image.voxel_count(); ++v)
    highest = std::max<int>(highest, labels.label(v));
  shown_ = highest > 0;
  if (shown_) {
    core::ImageVolume local = labels.image;
    local.origin = core::Vec3::Zero();
    local.direction = core::Mat3::Identity();
    image_ = vtkSmartPointer<vtkImageData>::New();
    core::volume_to_image_data(local, *image_);
    // One table entry per label value: 0 transparent, each label its colour at the opacity.
    table_->SetNumberOfTableValues(highest + 1);
    table_->SetTableRange(0.0, highest);
    table_->SetTableValue(0, 0.0, 0.0, 0.0, 0.0);
    for (int label = 1; label <= highest; ++label) {
      const auto c = label_colour(label);
      table_->SetTableValue(label, c[0], c[1], c[2], opacity_);
    }
    table_->Build();
    colours_->SetInputData(image_);
    auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        matrix->SetElement(r, c, labels.image.direction(r, c));
      matrix->SetElement(r, 3, labels.image.origin[r]);
    }
    for (int axis = 0; axis < 3; ++axis) {
      overlays_[axis]->SetUserMatrix(matrix);
      overlays_3d_[axis]->SetUserMatrix(matrix);
    }
  }
  sync();
}

void LabelOverlay::set_opacity(double opacity) {
  opacity_ = std::clamp(opacity, 0.0, 1.0);
  for (vtkIdType label = 1; label < table_->GetNumberOfTableValues(); ++label) {
    double rgba[4];
    table_->GetTableValue(label, rgba);
    table_->SetTableValue(label, rgba[0], rgba[1], rgba[2], opacity_);
  }
  table_->Modified();
  sync();
}

void LabelOverlay::set_shown_in_3d(bool shown) {
  shown_in_3d_ = shown;
  sync();
}

void LabelOverlay::sync() {
  if (syncing_) return;
  syncing_ = true;
  for (int axis = 0; axis < 3; ++axis) {
    const bool visible = shown_ && slices_->has_volume();
    for (auto* overlay : {overlays_[axis].GetPointer(), overlays_3d_[axis].GetPointer()}) {
      static_cast<vtkImageSliceMapper*>(overlay->GetMapper())->SetSliceNumber(slices_->slice(axis));
    }
    overlays_[axis]->SetVisibility(visible);
    overlays_3d_[axis]->SetVisibility(visible && shown_in_3d_);
    slices_->view(axis)->renderWindow()->Render();
    slices_->view(axis)->update();
  }
  view_->render();
  syncing_ = false;
}

}  // namespace viscera::studio
