#pragma once
/// The voxel grid of the distension flow (seed 000 §2.2: "by labeling the voxels of a grid
/// overlaid on the scene, these elements can be incorporated consistently into the numerical
/// solver"). A staggered (MAC) grid after Harlow & Welch 1965: pressure at cell centres, each
/// velocity component on the faces normal to it, so the projection has no checkerboard modes.
///
/// Cells are fluid, solid (wall, pathology, instrument, inflow — each with its own velocity, m/s)
/// or open (an outflow: pressure held at 0). A grid one cell thick in z is planar: no z flow and
/// no z coupling, a 2D flow (the lid-driven cavity of the validation).

#include <array>
#include <cstdint>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim::fluid {

enum class FlowCell : std::uint8_t {
  Fluid,  ///< the flow's unknowns
  Solid,  ///< no flow through; its velocity drives the faces and the no-slip wall next to it
  Open,   ///< an outflow: pressure 0, velocity free
};

/// State of one velocity face, derived from the two cells it separates.
enum class FaceState : std::uint8_t {
  Active,      ///< between two non-solid cells: advected, diffused and projected
  Prescribed,  ///< between a solid and a non-solid cell: the solid's normal velocity
  Inside,      ///< between two solid cells (or past the grid): their mean velocity
};

/// Integer coordinates of one cell; they may lie outside the grid.
struct CellCoord {
  int i = 0, j = 0, k = 0;
};

/// Sizes of one component's face array: the cell counts plus one along the component's axis.
struct FaceDims {
  int x = 0, y = 0, z = 0;
  int count() const { return x * y * z; }
  int index(int i, int j, int k) const { return i + x * (j + y * k); }
};

class FlowGrid {
 public:
  /// `nx`×`ny`×`nz` cells of edge `cell_size` m, the corner of cell (0,0,0) at `origin`; every
  /// cell fluid and at rest. Throws core::UsageError for a count below 1 or a size ≤ 0.
  FlowGrid(int nx, int ny, int nz, double cell_size, const core::Vec3& origin = core::Vec3::Zero());

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  double cell_size() const { return h_; }
  const core::Vec3& origin() const { return origin_; }
  bool planar() const { return nz_ == 1; }
  int cell_count() const { return nx_ * ny_ * nz_; }
  int cell_index(int i, int j, int k) const { return i + nx_ * (j + ny_ * k); }
  FaceDims face_dims(int axis) const {
    return {nx_ + (axis == 0), ny_ + (axis == 1), nz_ + (axis == 2)};
  }

  /// Labels a cell; `velocity` (m/s) is a solid cell's own (a moving lid, the sheath's inflow).
  /// Call update_faces() after a batch of labels.
  void set_cell(int i, int j, int k, FlowCell cell,
                const core::Vec3& velocity = core::Vec3::Zero());
  FlowCell cell(int i, int j, int k) const {
    return cells_[static_cast<std::size_t>(cell_index(i, j, k))];
  }
  /// Solid (at rest) outside the grid.
  FlowCell cell_or_solid(int i, int j, int k) const {
    if (!contains({i, j, k})) return FlowCell::Solid;
    return cell(i, j, k);
  }
  FlowCell cell_or_solid(const CellCoord& c) const { return cell_or_solid(c.i, c.j, c.k); }
  /// The cell holding `point` (m): ⌊(point − origin)/h⌋ on each axis, possibly outside the grid.
  CellCoord cell_of(const core::Vec3& point) const;
  bool contains(const CellCoord& c) const {
    return c.i >= 0 && c.j >= 0 && c.k >= 0 && c.i < nx_ && c.j < ny_ && c.k < nz_;
  }
  int cell_index(const CellCoord& c) const { return cell_index(c.i, c.j, c.k); }
  /// A solid cell's own velocity, m/s (zero outside the grid).
  core::Vec3 solid_velocity(int i, int j, int k) const {
    if (!contains({i, j, k})) return core::Vec3::Zero();
    return solid_velocity_[static_cast<std::size_t>(cell_index(i, j, k))];
  }
  /// Changes the velocity of solid cell (i,j,k) (m/s) and writes it into its six faces at once,
  /// without relabelling: the sheath's inflow from one step to the next. Throws
  /// core::UsageError for a cell that is not solid.
  void set_solid_velocity(int i, int j, int k, const core::Vec3& velocity);

  /// Recomputes each face's state from the cells and writes the solid velocities into the
  /// prescribed and inside faces; active faces keep their values.
  void update_faces();
  /// A number no other labelling of any grid has had: it changes with the update_faces() that
  /// follows a change of any cell's label (not of a solid's velocity alone), so a solver's
  /// structure built for one labelling knows when it is out of date.
  std::uint64_t labelling() const { return labelling_; }
  const std::vector<FaceState>& face_states(int axis) const { return states_[axis]; }

  /// Face velocities of component `axis` (0 x, 1 y, 2 z), m/s.
  std::vector<double>& velocity(int axis) { return velocity_[axis]; }
  const std::vector<double>& velocity(int axis) const { return velocity_[axis]; }
  /// Kinematic pressure p/ρ per cell, m²/s² (0 in open cells).
  std::vector<double>& pressure() { return pressure_; }
  const std::vector<double>& pressure() const { return pressure_; }

  /// Position of face (i,j,k) of component `axis`, m.
  core::Vec3 face_position(int axis, int i, int j, int k) const;
  /// Component `axis` of the velocity at `point` (m), trilinear over that component's faces,
  /// clamped to the grid; m/s.
  double sample(int axis, const core::Vec3& point) const;
  /// The same interpolation over `values`, one per face of component `axis`; `low` and `high`
  /// receive the smallest and largest of the corners used (the MacCormack limiter's bounds).
  double sample(int axis, const std::vector<double>& values, const core::Vec3& point,
                double* low = nullptr, double* high = nullptr) const;
  core::Vec3 velocity_at(const core::Vec3& point) const;
  /// The whole velocity at the centre of face (i,j,k) of component `axis`: its own component,
  /// the other two averaged over the four faces around it (m/s). The face must be active.
  core::Vec3 face_velocity(int axis, int i, int j, int k) const;
  /// Largest |∇·u| over fluid cells, 1/s.
  double max_divergence() const;

 private:
  int nx_, ny_, nz_;
  double h_;
  core::Vec3 origin_;
  std::vector<FlowCell> cells_;
  std::vector<core::Vec3> solid_velocity_;
  std::array<std::vector<double>, 3> velocity_;
  std::array<std::vector<FaceState>, 3> states_;
  std::vector<double> pressure_;
  /// The state and, for a face beside a solid, the velocity of face (i,j,k) of `axis`.
  void update_face(int axis, int i, int j, int k);

  std::uint64_t labelling_ = 0;
  bool relabelled_ = true;  ///< a label changed since the last update_faces()
};

}  // namespace viscera::sim::fluid
