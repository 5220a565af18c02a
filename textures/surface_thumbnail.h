#pragma once
/// Thumbnails of surfaces for the asset library (seed 001 §3.3: models archived for reuse): a
/// small shaded picture rendered in software — no window, no GPU — so the CLI and tests make
/// the same image everywhere.

#include "core/mesh/surface_mesh.h"
#include "core/scenario/material.h"
#include "textures/image8.h"

namespace viscera::textures {

/// An RGB image of `size` × `size` pixels of `surface` seen orthographically from the
/// direction (1, −1.5, 1) (above, in front, to the right), its bounding sphere filling 90 % of
/// the width; triangles are depth-buffered and shaded by a headlight on both sides (open
/// sheets show their back). Background (40, 44, 52), surface a tissue pink. The same surface
/// gives the same pixels. Throws core::UsageError for a size outside [16, 1024] or an empty or
/// non-finite surface.
Image8 render_surface_thumbnail(const core::SurfaceMesh& surface, int size = 128);

/// `image` scaled (area averaging) to fit `size` × `size` pixels with its aspect ratio kept, in
/// RGB. Throws core::UsageError for a size outside [16, 1024] or an empty image.
Image8 image_thumbnail(const Image8& image, int size = 128);

/// A plot of a material's stress-strain curve (seed 001 §3.2): axes from the origin, the
/// measured samples as light dots and the fitted cubic σ(ε) = c1 ε + c2 ε|ε| + c3 ε³ as a pink
/// line, over [0, the largest measured strain] (0.3 without samples) and [0, the largest
/// stress]. Throws core::UsageError for a size outside [16, 1024] or a curve without a cubic.
Image8 render_stress_strain_thumbnail(const core::StressStrainCurve& curve, int size = 128);

}  // namespace viscera::textures
