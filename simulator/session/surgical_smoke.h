#pragma once
/// Surgical smoke of coagulation and the steaming of the laparoscope's lens (seed 001 §4.2;
/// issue 19 §4).
///
/// Smoke: while current flows through tissue, a puff leaves the coagulation site every
/// `puff_interval` s. Seed 001 hangs the smoke's textured circles "along a time dependent
/// animated spline curve with increasing size along the curve", transparency "increasing …
/// from bottom to top": a puff of age a rises against gravity at `rise_speed` and sways across
/// it on a Lissajous path (the animated curve, its phase set by the puff's index),
///   c(a) = origin + a·v_rise·up + sway·(sin(ωa + φ)·e₁ + sin(0.7ωa + 2φ)·e₂) · min(1, a/τ_s),
/// its radius grows linearly from `birth_radius` to `death_radius` over its life and its
/// opacity fades in over 0.2 s and out linearly to zero at the end of its life. Suction removes
/// the puffs near its tip.
///
/// Lens steaming: seed 001 fogs the lens "in dependence of the density of the 3d smoke texture
/// and the coagulation duration", by a polygon in front of the camera whose transparency
/// decreases gradually. The fog F ∈ [0, 1] grows while the lens is within `lens_reach` m of the
/// coagulating tissue, dF/dt = fog_rate · (1 − F), and with the smoke at the lens (the opacity of
/// the puffs whose circle holds the lens), and clears exponentially with `lens_clear_time`
/// (the stated choices; the seed gives no law).
///
/// Deterministic: no random numbers; the same inputs give the same puffs.

#include <limits>
#include <optional>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

struct SmokeOptions {
  double puff_interval = 0.05;   ///< s between puffs while coagulating
  double life = 6.0;             ///< s a puff lasts
  double rise_speed = 0.01;      ///< m/s against gravity
  double sway = 0.004;           ///< m, amplitude of the animated path across the rise
  double sway_frequency = 1.2;   ///< rad/s, ω
  double birth_radius = 0.002;   ///< m
  double death_radius = 0.012;   ///< m
  double birth_opacity = 0.2;    ///< peak opacity of one puff, 0…1
  double visible_opacity = 0.1;  ///< the field counts as smoky while the densest point exceeds it
  double fog_rate = 0.3;         ///< 1/s, lens fogging near coagulating tissue
  double lens_reach = 0.03;      ///< m
  double lens_clear_time = 6.0;  ///< s, e-folding time of the fog clearing
};

/// One puff as the view draws it: a camera-facing textured circle.
struct SmokeBillboard {
  core::Vec3 centre = core::Vec3::Zero();  ///< m
  double radius = 0.0;                     ///< m
  double opacity = 0.0;                    ///< 0…1
  int index = 0;                           ///< puff number, for its texture offset
};

class SurgicalSmoke {
 public:
  explicit SurgicalSmoke(const SmokeOptions& options = {});

  /// One step of `dt` s ending at `time` s: a puff from `coagulating_at` (m) when current flows
  /// there, the puffs rise, the lens at `lens` (m) fogs or clears. `up` is the unit direction
  /// smoke rises in.
  void step(double time, double dt, const std::optional<core::Vec3>& coagulating_at,
            const core::Vec3& up, const core::Vec3& lens);
  /// Suction at `tip` (m) removes the puffs whose centre lies within `radius` m. Returns how
  /// many.
  int suck(const core::Vec3& tip, double radius, double time);

  /// The puffs alive at `time` s (the time of the last step).
  std::vector<SmokeBillboard> billboards() const;
  /// Opacity of the smoke over the point `p` (m): 1 − Π (1 − α_i) over the puffs holding p.
  double opacity_at(const core::Vec3& p) const;
  double lens_fog() const { return fog_; }  ///< 0 (clear) … 1
  double peak_lens_fog() const { return peak_fog_; }
  /// s with the field visibly smoky: some puff's centre under a stacked opacity above
  /// `visible_opacity`. That check is O(n²) in the puffs, so step() makes it only when puffs
  /// were added or removed (by step() or suck()) or `puff_interval` s after the last one, and
  /// counts the steps in between as it found; each change between smoky and clear may be
  /// counted up to one puff interval late (a step-by-step check would differ by that much).
  double smoke_time() const { return smoke_time_; }
  int puffs_emitted() const { return emitted_; }

 private:
  struct Puff {
    core::Vec3 origin;
    core::Vec3 up;
    double born = 0.0;  ///< s
    int index = 0;
  };
  SmokeBillboard billboard(const Puff& puff) const;
  static double stacked_opacity(const std::vector<SmokeBillboard>& puffs, const core::Vec3& point);

  SmokeOptions options_;
  std::vector<Puff> puffs_;
  double time_ = 0.0;
  double next_puff_ = 0.0;  ///< s, the earliest time of the next puff
  double fog_ = 0.0, peak_fog_ = 0.0, smoke_time_ = 0.0;
  int emitted_ = 0;
  bool smoky_ = false;          ///< the last densest-point check found the field smoky
  bool puffs_changed_ = false;  ///< puffs added or removed since that check
  double smoky_checked_at_ = -std::numeric_limits<double>::infinity();  ///< s, its time
};

}  // namespace viscera::sim
