#pragma once
/// Shared by the rendering tests: one hysteroscopy package built by the `viscera` program, and
/// statistics of rendered frames.

#include <vtkSmartPointer.h>

#include <array>
#include <filesystem>

#include "core/scenario/scenario.h"

class vtkImageData;

namespace viscera::testing {

/// A hysteroscopy package from `viscera new --template hysteroscopy --seed 7` with its
/// textures baked (`viscera bake`), built once.
struct Patient {
  std::filesystem::path package;
  core::Scenario scenario;
};
const Patient& hysteroscopy_patient();

/// Statistics of the pixels inside the round field of radius `field` × half the image height.
struct FrameStatistics {
  double lit_fraction = 0.0;    ///< pixels brighter than 8 of 255
  double mean_luminance = 0.0;  ///< 0…255, over all pixels in the field
  double luminance_stddev = 0.0;
  std::array<double, 3> chromaticity{0.0, 0.0, 0.0};  ///< Σr, Σg, Σb over Σ(r+g+b), lit pixels
};
FrameStatistics frame_statistics(vtkImageData* frame, double field);

/// Mean |a − b| over all channels (0…255), inside the round field `field` (≤ 0: everywhere).
double mean_abs_difference(vtkImageData* a, vtkImageData* b, double field = 0.0);

/// Mean luminance of the four 12 × 12 corners.
double corner_luminance(vtkImageData* frame);

}  // namespace viscera::testing
