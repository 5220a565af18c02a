#pragma once
/// The flow grid of a hollow organ's cavity (seed 000 §2.2: "by labeling the voxels of a grid
/// overlaid on the scene, these elements can be incorporated consistently into the numerical
/// solver"): the distension fluid fills the uterine cavity, the pocket the wall's surface leaves
/// open, and the tissue around it is solid.
///
/// Cells of `cell_size` m cover the bounding box of the cavity wall — the surface vertices whose
/// "cavity" mark is 1, as the hysteroscopy template marks them — plus `margin` cells. A cell is
/// fluid when its centre lies outside the tissue (the closed, outward surface; parity of the
/// crossings of a ray along x through its row) and in the largest face-connected pocket of such
/// cells; every other cell is solid at rest. Part of viscera_sim (it casts rays in the camera's
/// surface BVH).

#include <span>
#include <vector>

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

/// Labels the cavity of the surface `positions`/`triangles` (current, deformed positions, m).
/// Throws core::InputError when no vertex is marked 1 in `cavity_marks` (one per vertex) or no
/// cell is left fluid; core::UsageError for a cell size ≤ 0 or a grid above 256³ cells.
FlowGrid label_cavity(std::span<const core::Vec3> positions,
                      const std::vector<core::Triangle>& triangles,
                      const std::vector<double>& cavity_marks, double cell_size, int margin = 1);

}  // namespace viscera::sim::fluid
