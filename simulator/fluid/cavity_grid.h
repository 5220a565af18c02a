#pragma once
/// The flow grid of a hollow organ's cavity (seed 000 §2.2: "by labeling the voxels of a grid
/// overlaid on the scene, these elements can be incorporated consistently into the numerical
/// solver"): the distension fluid fills the uterine cavity, the pocket the wall's surface leaves
/// open, and the tissue around it is solid.
///
/// Cells of `cell_size` m cover the bounding box of the cavity wall — the surface vertices whose
/// "cavity" mark is 1, as the hysteroscopy template marks them — plus `margin` cells. A cell is
/// fluid when its centre lies outside the tissue (the closed, outward surface; parity of the
/// crossings of a ray along x through its row) and in the face-connected pocket of such cells
/// that the marked wall faces; every other cell is solid at rest. Part of viscera_sim (it casts
/// rays in the camera's surface BVH).

#include <span>
#include <vector>

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

/// Labels the cavity of the surface `positions`/`triangles` (current, deformed positions, m):
/// the cavity is the pocket beside the most marked vertices (the largest when none is). Throws
/// core::InputError when no vertex is marked 1 in `cavity_marks` (one per vertex) or no cell is
/// left fluid; core::UsageError for a cell size ≤ 0 or a grid above 256³ cells.
FlowGrid label_cavity(std::span<const core::Vec3> positions,
                      const std::vector<core::Triangle>& triangles,
                      const std::vector<double>& cavity_marks, double cell_size, int margin = 1);

/// Relabels `grid` in place (same cells, same frame) after the wall has moved to `positions`:
/// the cavity is now the pocket that shares the most cells with the grid's current fluid and
/// open cells. Cells it leaves out become solid at rest; the cells that join it become fluid
/// with their faces' velocities as they were. Call before labelling instruments and obstacles
/// again (each relabelling starts from the wall alone). Returns the number of cells whose label
/// changed. Throws core::InputError when no pocket meets the current cavity (the wall has
/// collapsed onto it).
int relabel_cavity(FlowGrid& grid, std::span<const core::Vec3> positions,
                   const std::vector<core::Triangle>& triangles);

/// Makes solid (at `velocity`, m/s) every fluid or open cell of `grid` whose centre lies inside
/// the closed surface `positions`/`triangles` — a polyp, a myoma, a chip in the cavity. Returns
/// the number of cells it labelled. Call update_faces() afterwards.
int mark_inside_solid(FlowGrid& grid, std::span<const core::Vec3> positions,
                      const std::vector<core::Triangle>& triangles,
                      const core::Vec3& velocity = core::Vec3::Zero());

/// Makes solid every face-connected pocket of non-solid cells that has no open cell — fluid a
/// pathology or the sheath has cut off, whose pressure nothing fixes — except, when no pocket
/// has an open cell, the largest. Returns the number of cells closed. Call update_faces()
/// afterwards.
int close_stranded_pockets(FlowGrid& grid);

}  // namespace viscera::sim::fluid
