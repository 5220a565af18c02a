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
///   "Labels" (issue 23 §5): a label image coloured by label — each distinct non-zero value its
///     own colour from a fixed palette at opacity 0.5, 0 transparent, nearest-voxel sampling so
///     labels do not blend.
/// preset_for_data() picks one from the data when a volume is opened.
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

/// "CT soft tissue", "CT bone", "MR default", "Labels", in that order ("Labels" has no fixed
/// functions: they come from the volume's label values).
const std::vector<VolumePreset>& volume_presets();

/// The volume prop of one image volume, placed in the world by its origin and direction.
class VolumeRendering {
 public:
  VolumeRendering();

  /// Renders `volume` from now on (the preset stays).
  void set_volume(const core::ImageVolume& volume);
  bool has_volume() const { return image_ != nullptr; }
  /// Forgets the volume (File ▸ Close image volume); the prop should be hidden.
  void clear();
  /// Applies a preset by name; returns false for an unknown name.
  bool apply_preset(const std::string& name);
  const std::string& preset() const { return preset_; }
  /// The preset the data asks for: "Labels" for whole-number voxels of at most 64 distinct
  /// values (a label image), "CT soft tissue" when values reach below −200 (Hounsfield units),
  /// else "MR default". "CT soft tissue" without a volume.
  std::string preset_for_data() const;
  /// The distinct voxel values of a whole-number volume (at most 257 collected), ascending.
  const std::vector<double>& distinct_values() const { return distinct_; }
  /// The ray caster of the last render: "GPU", "CPU" or "none" (not rendered yet, or no
  /// supported path).
  std::string last_render_mode() const;
  /// The prop to add to a renderer.
  vtkVolume* prop() const { return volume_; }

 private:
  void apply(const VolumePreset& preset);
  void apply_labels();

  vtkSmartPointer<vtkImageData> image_;
  vtkSmartPointer<vtkVolume> volume_;
  std::string preset_;
  std::array<double, 2> range_{0.0, 1.0};
  std::vector<double> distinct_;
  bool whole_numbers_ = false;
};

}  // namespace viscera::studio
