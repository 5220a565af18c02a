#pragma once
/// The pool of fluid at the bottom of the abdomen in a laparoscopy (seed 001 §4.3; specs §4.8):
/// irrigation water and blood that come to rest gather "realised by a deformable flat object"
/// whose height follows the amount, "with the knowledge of the irrigation amount, the increase of
/// the pool height is calculated". Here the pool is a flat surface across gravity over the
/// lowest point of the scene, its height h = V / A_pool (specs §4.8 [derivation]) with V the
/// water and blood in it and A_pool a fixed area: fluid spreads over the pelvic floor, whose
/// walls are steep compared with a few centimetres of depth. The pool keeps water and blood
/// apart in its books (the seed colours the pool by their amounts, §5.1.2) but mixes them: the
/// suction cannula takes both in proportion.
///
/// Volumes in m³ (the report shows ml), lengths in m, rates in m³/s.

#include "core/math_types.h"

namespace viscera::sim::fluid {

/// A pool's contents, or a flow of them.
struct PoolVolumes {
  double water = 0.0;  ///< m³ of irrigation fluid
  double blood = 0.0;  ///< m³ of blood
  double total() const { return water + blood; }
};

/// The suction valve of a suction–irrigation cannula (5 mm, on wall suction).
struct SuctionOptions {
  /// m³/s drawn off while the valve is open over fluid: 15 ml/s (0.9 l/min), what a 5 mm
  /// cannula on wall suction of about −200 mmHg clears from a pool (suction units are rated at
  /// 1–2 l/min of water through open tubing; the cannula's bore and side holes lower it).
  double rate = 15e-6;
  /// m: the cannula draws fluid when its tip is under the pool's surface or less than this
  /// above it (its side holes sit within the last 5 mm of the tip).
  double reach = 0.005;
};

/// A pool across gravity over the lowest point of the scene (A_pool: kPelvicPoolArea unless
/// stated).
class FluidPool {
 public:
  /// The pouch of Douglas and the pelvic floor below the uterus, about 7 × 7 cm, where fluid
  /// collects in a patient lying supine or head-down: 50 cm², so 100 ml stand 2 cm deep.
  static constexpr double kPelvicPoolArea = 0.005;

  /// A pool whose floor is `floor` (m, the lowest point of the scene), under gravity pointing
  /// along `down` (any length but zero), spread over `area` m². Throws core::InputError for a
  /// zero or non-finite `down`, a non-finite floor or an area that is not positive.
  FluidPool(const core::Vec3& floor, const core::Vec3& down, double area = kPelvicPoolArea);

  /// Adds `volume` m³ (≥ 0; throws core::InputError otherwise) of irrigation water / blood.
  void add_water(double volume);
  void add_blood(double volume);

  /// Takes out up to `volume` m³, water and blood in their proportion in the pool; returns what
  /// was taken (all of it when the pool holds less). Throws core::InputError for a negative
  /// volume.
  PoolVolumes remove(double volume);

  /// The suction cannula with its valve open at `tip` (m) for `dt` s: removes rate · dt when the
  /// tip is under the surface or within the reach above it, nothing otherwise. Returns what it
  /// drew off.
  PoolVolumes suck(const core::Vec3& tip, const SuctionOptions& suction, double dt);

  /// m the surface stands above the floor: V / A_pool.
  double height() const { return contents_.total() / area_; }
  /// m `point` lies below the surface along gravity (negative above it).
  double depth(const core::Vec3& point) const;
  /// The surface point straight under (or over) `point` along gravity, m.
  core::Vec3 surface_point(const core::Vec3& point) const;

  const PoolVolumes& contents() const { return contents_; }
  /// Blood over all fluid in the pool, 0 for an empty pool.
  double blood_fraction() const;
  /// Everything that ever came in, and everything suctioned, m³.
  const PoolVolumes& received() const { return received_; }
  const PoolVolumes& suctioned() const { return suctioned_; }

  const core::Vec3& floor() const { return floor_; }
  const core::Vec3& down() const { return down_; }  ///< unit
  double area() const { return area_; }

 private:
  core::Vec3 floor_;
  core::Vec3 down_;
  double area_;
  PoolVolumes contents_, received_, suctioned_;
};

}  // namespace viscera::sim::fluid
