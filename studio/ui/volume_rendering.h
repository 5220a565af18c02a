#pragma once
/// Direct volume rendering of the opened image volume in the 3D view (issue 9 §2): ray casting
/// through vtkSmartVolumeMapper (GPU ray casting in OpenGL, which Mesa's llvmpipe runs under
/// Xvfb; VTK falls back to its CPU ray caster where the GPU path is unsupported), with
/// transfer-function presets. Each preset is a piecewise-linear colour and opacity function of
/// the voxel value:
///   "CT soft tissue" (Hounsfield units): transparent below −100 HU (air, fat), opacity rising
///     to 0.15 at 40 HU and 0.35 at 150 HU, 0.5 from 400 HU; colours from dark red muscle to
///     pale pink and white;
///   "CT bone" (HU): transparent below 150 HU, 0.2 at 300 HU, 0.85 from 1000 HU; ivory;
///   "MR default" (normalised intensity t = (v − min) / (max − min) over the volume's range,
///     MR having no absolute scale): transparent below t = 0.1, 0.3 at 0.5, 0.8 at 1; warm grey.
/// Gradient-free (no shading) so the image depends only on the functions and the geometry.

#include <vtkImageData.h>
#include <vtkSmartPointer.h>
#include <vtkVolume.h>

#include <array>
#include <string>
#include <vector>

#include "core/image/image_volume.h"

namespace viscera::studio {

/// A transfer-function preset: (value, r, g, b) colour points and (value, opacity) points,
/// values in the volume's units, or normalised to [0, 1] over its range when `normalised`.
struct VolumePreset {
  std::string name;
  bool normalised = false;
  std::vector<std::array<double, 4>> colour;
  std::vector<std::array<double, 2>> opacity;
};

/// "CT soft tissue", "CT bone", "MR default", in that order.
const std::vector<VolumePreset>& volume_presets();

/// The volume prop of one image volume, placed in the world by its origin and direction.
class VolumeRendering {
 public:
  VolumeRendering();

  /// Renders `volume` from now on (the preset stays).
  void set_volume(const core::ImageVolume& volume);
  bool has_volume() const { return image_ != nullptr; }
  /// Applies a preset by name; returns false for an unknown name.
  bool apply_preset(const std::string& name);
  const std::string& preset() const { return preset_; }
  /// The ray caster of the last render: "GPU", "CPU" or "none" (not rendered yet, or no
  /// supported path).
  std::string last_render_mode() const;
  /// The prop to add to a renderer.
  vtkVolume* prop() const { return volume_; }

 private:
  void apply(const VolumePreset& preset);

  vtkSmartPointer<vtkImageData> image_;
  vtkSmartPointer<vtkVolume> volume_;
  std::string preset_;
  std::array<double, 2> range_{0.0, 1.0};
};

}  // namespace viscera::studio
