#pragma once
/// Waves on the laparoscopy's pool (seed 001 §4.3: the pool is "a deformable flat object" and
/// waves come from the irrigation jet's impacts; specs §4.8 item 6). The surface's elevation η
/// (m) about the pool's level V/A_pool is a height field on a square grid over the pool's disc,
/// moved by the linear shallow-water wave equation
///   ∂²η/∂t² = g H ∇²η − γ ∂η/∂t
/// with H the pool's depth (waves run at √(g H): 0.44 m/s in 2 cm of water) and reflecting rims.
///
/// Decided where the seed is silent:
/// - A drop of volume V falling into the pool at normal speed v_n raises the water where it
///   lands by V/A_cell and gives the column under it (mass ρ A_cell H) its momentum,
///   ∂η/∂t −= ρ V v_n / (ρ A_cell H); both are spread back over the whole pool (the level's
///   rise is FluidPool's), so ∫η dA stays 0: the waves move water, never make or lose it.
/// - γ = 3 /s: a slosh dies out in a second or two, as it does in the pelvis (the seed gives no
///   figure; viscous damping alone, 2ν k², would leave centimetre waves ringing for minutes in
///   an open basin, but the pelvic floor is tissue, not a rigid wall, and takes their energy).
/// - Explicit symplectic Euler, sub-stepped below the grid's stable step dx/(√2 c).
///
/// Deterministic: the same landings in the same order give the same bits.

#include <vector>

#include "core/math_types.h"

namespace viscera::sim::fluid {

class PoolWaves {
 public:
  static constexpr double kDamping = 3.0;   ///< γ in 1/s
  static constexpr double kGravity = 9.81;  ///< m/s²

  /// Waves on a disc of `area` m² across gravity `down` (any length but zero) centred over
  /// `floor` (m), `cells` grid cells across its diameter. Throws core::InputError for an area
  /// that is not positive, a zero `down` or fewer than 4 cells.
  PoolWaves(const core::Vec3& floor, const core::Vec3& down, double area, int cells = 32);

  /// A drop of `volume` m³ lands at `point` (m; projected along gravity onto the disc, points
  /// beyond the rim land at the rim) moving at `velocity` m/s, in a pool `depth` m deep.
  void drop_lands(const core::Vec3& point, const core::Vec3& velocity, double volume, double depth);
  /// Moves the waves through `dt` s in a pool `depth` m deep (an empty pool: they vanish).
  void step(double dt, double depth);

  /// η in m at the point of the disc over `point` (bilinear between cell centres).
  double elevation(const core::Vec3& point) const;
  /// η at in-plane coordinates (u, v) m from the disc's centre along axes().
  double elevation_at(double u, double v) const;
  /// ∫η dA over the disc in m³ (0 to rounding: the waves move water, never make it).
  double displaced_volume() const;
  /// The largest |η| in m.
  double largest_elevation() const;

  /// Two unit axes across gravity, u × v = up; the disc's radius in m and its centre's
  /// projection: the floor.
  const core::Vec3& u_axis() const { return u_; }
  const core::Vec3& v_axis() const { return v_; }
  double radius() const { return radius_; }
  int cells() const { return n_; }
  /// η per cell, row-major (v rows, u columns), 0 outside the disc.
  const std::vector<double>& heights() const { return eta_; }

 private:
  bool inside(int i, int j) const { return inside_[static_cast<std::size_t>(j * n_ + i)] != 0; }
  /// The cell under in-plane (u, v), clamped into the disc.
  std::size_t cell_at(double u, double v) const;
  /// Adds `amount` to cell c of `field` and takes it back evenly from every cell of the disc
  /// (the field's integral over the disc is unchanged).
  void spread(std::vector<double>& field, std::size_t c, double amount) const;

  core::Vec3 floor_, up_, u_, v_;
  double radius_ = 0.0, dx_ = 0.0;
  int n_ = 0;
  std::vector<char> inside_;
  int inside_count_ = 0;
  std::vector<double> eta_, rate_, laplacian_;
  bool still_ = true;  ///< η and ∂η/∂t are zero everywhere: nothing to step
};

}  // namespace viscera::sim::fluid
