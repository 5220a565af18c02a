#include "studio/ui/volume_rendering.h"

#include <vtkColorTransferFunction.h>
#include <vtkMatrix4x4.h>
#include <vtkPiecewiseFunction.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/image/image_volume_io.h"

namespace viscera::studio {

const std::vector<VolumePreset>& volume_presets() {
  static const std::vector<VolumePreset> presets = {
      {"CT soft tissue",
       false,
       {{-1000.0, 0.0, 0.0, 0.0},
        {-100.0, 0.45, 0.15, 0.1},
        {40.0, 0.8, 0.35, 0.3},
        {150.0, 0.95, 0.65, 0.55},
        {400.0, 1.0, 0.9, 0.85},
        {3000.0, 1.0, 1.0, 1.0}},
       {{-1000.0, 0.0}, {-100.0, 0.0}, {40.0, 0.15}, {150.0, 0.35}, {400.0, 0.5}, {3000.0, 0.5}}},
      {"CT bone",
       false,
       {{-1000.0, 0.0, 0.0, 0.0},
        {150.0, 0.55, 0.25, 0.15},
        {300.0, 0.9, 0.82, 0.56},
        {1000.0, 1.0, 1.0, 0.9},
        {3000.0, 1.0, 1.0, 1.0}},
       {{-1000.0, 0.0}, {150.0, 0.0}, {300.0, 0.2}, {1000.0, 0.85}, {3000.0, 0.85}}},
      {"MR default",
       true,
       {{0.0, 0.0, 0.0, 0.0}, {0.3, 0.55, 0.4, 0.3}, {0.7, 0.9, 0.75, 0.6}, {1.0, 1.0, 0.85, 0.7}},
       {{0.0, 0.0}, {0.1, 0.0}, {0.5, 0.3}, {1.0, 0.8}}},
      {"Labels", false, {}, {}},
  };
  return presets;
}

VolumeRendering::VolumeRendering() {
  volume_ = vtkSmartPointer<vtkVolume>::New();
  auto mapper = vtkSmartPointer<vtkSmartVolumeMapper>::New();
  mapper->SetRequestedRenderModeToDefault();
  mapper->SetBlendModeToComposite();
  volume_->SetMapper(mapper);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  volume_->SetProperty(property);
  volume_->SetPickable(false);
  apply(volume_presets().front());
}

namespace {

/// Label colours: warm first, then well separated hues.
constexpr std::array<std::array<double, 3>, 8> kLabelPalette = {{{0.92, 0.30, 0.25},
                                                                 {0.35, 0.75, 0.35},
                                                                 {0.30, 0.50, 0.95},
                                                                 {0.95, 0.80, 0.30},
                                                                 {0.75, 0.40, 0.85},
                                                                 {0.30, 0.80, 0.80},
                                                                 {0.95, 0.55, 0.20},
                                                                 {0.60, 0.60, 0.60}}};

}  // namespace

std::string VolumeRendering::preset_for_data() const {
  if (image_ == nullptr) return "CT soft tissue";
  if (whole_numbers_ && !distinct_.empty() && distinct_.size() <= 64 && distinct_.front() >= 0.0)
    return "Labels";
  if (range_[0] < -200.0) return "CT soft tissue";
  return "MR default";
}

void VolumeRendering::apply_labels() {
  preset_ = "Labels";
  auto colour = vtkSmartPointer<vtkColorTransferFunction>::New();
  auto opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
  colour->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  opacity->AddPoint(0.0, 0.0);
  std::size_t index = 0;
  const bool labels = whole_numbers_ && distinct_.size() <= 64;
  for (const double value : distinct_) {
    if (value == 0.0 || !labels) continue;
    const auto& c = kLabelPalette[index++ % kLabelPalette.size()];
    // A plateau of one colour and opacity around each label value.
    colour->AddRGBPoint(value - 0.49, c[0], c[1], c[2]);
    colour->AddRGBPoint(value + 0.49, c[0], c[1], c[2]);
    opacity->AddPoint(value - 0.5, 0.0);
    opacity->AddPoint(value - 0.49, 0.5);
    opacity->AddPoint(value + 0.49, 0.5);
    opacity->AddPoint(value + 0.5, 0.0);
  }
  if (index == 0) {  // not a label image: a warm ramp over the range
    colour->AddRGBPoint(range_[1], kLabelPalette[0][0], kLabelPalette[0][1], kLabelPalette[0][2]);
    opacity->AddPoint(range_[0] + 0.1 * (range_[1] - range_[0]), 0.0);
    opacity->AddPoint(range_[1], 0.6);
  }
  volume_->GetProperty()->SetColor(colour);
  volume_->GetProperty()->SetScalarOpacity(opacity);
  volume_->GetProperty()->SetInterpolationTypeToNearest();
  double spacing = 0.001;
  if (image_ != nullptr) spacing = image_->GetSpacing()[0];
  volume_->GetProperty()->SetScalarOpacityUnitDistance(spacing);
}

void VolumeRendering::clear() {
  image_ = nullptr;
  volume_->SetVisibility(false);
}

void VolumeRendering::set_volume(const core::ImageVolume& volume) {
  // As in the slice views: the image keeps index geometry, origin and direction go into the
  // prop's user matrix.
  core::ImageVolume local = volume;
  local.origin = core::Vec3::Zero();
  local.direction = core::Mat3::Identity();
  image_ = vtkSmartPointer<vtkImageData>::New();
  core::volume_to_image_data(local, *image_);
  image_->GetScalarRange(range_.data());
  // Whole-number voxels and their distinct values (a label image has a few).
  whole_numbers_ = volume.scalar_type != core::ScalarType::Float32 &&
                   volume.scalar_type != core::ScalarType::Float64;
  std::set<double> values;
  for (std::size_t v = 0; v < volume.voxel_count() && whole_numbers_ && values.size() <= 256; ++v)
    values.insert(volume.value(v));
  distinct_.assign(values.begin(), values.end());
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      matrix->SetElement(r, c, volume.direction(r, c));
    matrix->SetElement(r, 3, volume.origin[r]);
  }
  volume_->SetUserMatrix(matrix);
  volume_->GetMapper()->SetInputDataObject(image_);
  apply_preset(preset_);
}

std::string VolumeRendering::last_render_mode() const {
  switch (static_cast<vtkSmartVolumeMapper*>(volume_->GetMapper())->GetLastUsedRenderMode()) {
    case vtkSmartVolumeMapper::GPURenderMode:
      return "GPU";
    case vtkSmartVolumeMapper::RayCastRenderMode:
      return "CPU";
    default:
      return "none";
  }
}

bool VolumeRendering::apply_preset(const std::string& name) {
  if (name == "Labels") {
    apply_labels();
    return true;
  }
  for (const auto& preset : volume_presets()) {
    if (preset.name == name) {
      apply(preset);
      return true;
    }
  }
  return false;
}

void VolumeRendering::apply(const VolumePreset& preset) {
  preset_ = preset.name;
  volume_->GetProperty()->SetInterpolationTypeToLinear();
  const double low = preset.normalised ? range_[0] : 0.0;
  const double scale = preset.normalised ? std::max(range_[1] - range_[0], 1e-12) : 1.0;
  auto colour = vtkSmartPointer<vtkColorTransferFunction>::New();
  for (const auto& [value, r, g, b] : preset.colour)
    colour->AddRGBPoint(low + scale * value, r, g, b);
  auto opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
  for (const auto& [value, alpha] : preset.opacity)
    opacity->AddPoint(low + scale * value, alpha);
  volume_->GetProperty()->SetColor(colour);
  volume_->GetProperty()->SetScalarOpacity(opacity);
  // Opacity per unit length of about one voxel (VTK's default is 1 world unit, here 1 m).
  double spacing = 0.001;
  if (image_ != nullptr) spacing = image_->GetSpacing()[0];
  volume_->GetProperty()->SetScalarOpacityUnitDistance(spacing);
}

}  // namespace viscera::studio
