#pragma once
/// Trilinear interpolation of one velocity component over its faces of a MAC grid, with the
/// grid's constants (offsets, strides, clamps) taken once, for the advection's inner loops: the
/// same values as FlowGrid::sample, which the semi-Lagrangian step calls millions of times a
/// second.

#include <algorithm>
#include <vector>

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

class FaceSampler {
 public:
  FaceSampler(const FlowGrid& grid, int axis) {
    const FaceDims d = grid.face_dims(axis);
    const int n[3] = {d.x, d.y, d.z};
    const int stride[3] = {1, d.x, d.x * d.y};
    inverse_h_ = 1.0 / grid.cell_size();
    for (int a = 0; a < 3; ++a) {
      // Faces of this component sit at whole indices along its own axis, half indices across.
      offset_[a] = grid.origin()[a] * inverse_h_ + (a == axis ? 0.0 : 0.5);
      upper_[a] = static_cast<double>(n[a] - 1);
      last_lower_[a] = std::max(n[a] - 2, 0);
      stride_[a] = n[a] > 1 ? stride[a] : 0;
    }
  }

  /// The component at `point` (m), clamped to the grid; `low`/`high` (when given) receive the
  /// smallest and largest of the eight corners used.
  double operator()(const double* values, const core::Vec3& point, double* low = nullptr,
                    double* high = nullptr) const {
    return at_index(values, point[0] * inverse_h_ - offset_[0], point[1] * inverse_h_ - offset_[1],
                    point[2] * inverse_h_ - offset_[2], low, high);
  }

  /// The same at face-index coordinates (x, y, z): face (i,j,k) of this component sits at
  /// (i, j, k) — what the advection's back-traces produce without going through metres.
  double at_index(const double* values, double x, double y, double z, double* low = nullptr,
                  double* high = nullptr) const {
    const double u[3] = {x, y, z};
    int base = 0;
    double t[3];
    for (int a = 0; a < 3; ++a) {
      // Written so that a NaN coordinate lands on 0 rather than on an index of no face.
      const double c = u[a] > 0.0 ? (u[a] < upper_[a] ? u[a] : upper_[a]) : 0.0;
      const int lo = std::min(static_cast<int>(c), last_lower_[a]);
      t[a] = stride_[a] != 0 ? c - lo : 0.0;
      base += lo * stride_[a];
    }
    const double* p = values + base;
    const int sx = stride_[0], sy = stride_[1], sz = stride_[2];
    const double c000 = p[0], c100 = p[sx], c010 = p[sy], c110 = p[sx + sy];
    const double c001 = p[sz], c101 = p[sx + sz], c011 = p[sy + sz], c111 = p[sx + sy + sz];
    if (low != nullptr && high != nullptr) {
      *low = std::min(std::min(std::min(c000, c100), std::min(c010, c110)),
                      std::min(std::min(c001, c101), std::min(c011, c111)));
      *high = std::max(std::max(std::max(c000, c100), std::max(c010, c110)),
                       std::max(std::max(c001, c101), std::max(c011, c111)));
    }
    const double x00 = c000 + t[0] * (c100 - c000);
    const double x10 = c010 + t[0] * (c110 - c010);
    const double x01 = c001 + t[0] * (c101 - c001);
    const double x11 = c011 + t[0] * (c111 - c011);
    const double y0 = x00 + t[1] * (x10 - x00);
    const double y1 = x01 + t[1] * (x11 - x01);
    return y0 + t[2] * (y1 - y0);
  }

 private:
  double inverse_h_ = 1.0;
  double offset_[3] = {0.0, 0.0, 0.0};  ///< origin / h plus the half-cell offset, in cells
  double upper_[3] = {0.0, 0.0, 0.0};   ///< largest face coordinate along each axis
  int last_lower_[3] = {0, 0, 0};       ///< largest lower-corner index along each axis
  int stride_[3] = {0, 0, 0};           ///< 0 along an axis with a single face
};

/// The whole velocity at a point from the grid's current faces (a planar grid has no z flow).
class VelocitySampler {
 public:
  explicit VelocitySampler(const FlowGrid& grid)
      : grid_(grid),
        components_{FaceSampler(grid, 0), FaceSampler(grid, 1), FaceSampler(grid, 2)} {}

  core::Vec3 operator()(const core::Vec3& point) const {
    return {components_[0](grid_.velocity(0).data(), point),
            components_[1](grid_.velocity(1).data(), point),
            grid_.planar() ? 0.0 : components_[2](grid_.velocity(2).data(), point)};
  }
  const FaceSampler& component(int axis) const { return components_[axis]; }

 private:
  const FlowGrid& grid_;
  FaceSampler components_[3];
};

}  // namespace viscera::sim::fluid
