#pragma once
/// How deep a resection loop's sweep went into the organ's wall, against the wall's thickness
/// there (issue 17 §5; seed 000 §1.1.1 and §2.1: cutting into the myometrium "is limited to a
/// relatively thin layer", and perforation means "immediate termination of the intervention").
///
/// The loop cuts pathology bodies only (loop_resection.h); where its swept surface enters the
/// wall — under a polyp's base, through a myoma's bed — that wall tissue is what its current
/// would have cut, so the gauge measures it on the sweep, not on the mesh.
///
/// Decided where the seed is silent: measured on the wall as it is when the pedal comes up (the
/// distended wall is the one the loop cut). For each vertex of the swept surface, the nearest
/// point p of the cavity's wall (cavity_pressure.h: the surface marked "cavity", normal n out of
/// the tissue) tells on which side it lies; a vertex behind it ((v − p)·n < 0) is |v − p| into
/// the wall, and the wall there is as thick as the ray from p along −n runs through the tissue
/// to the organ's outer surface. A vertex behind the cavity's wall and beyond that far surface
/// went through the wall: a perforation. The wall the sweep took off lies between the swept
/// surface and the cavity's surface: its volume is the sum over the swept triangles of their
/// area projected on the cavity's surface times their vertices' mean depth (a prism per
/// triangle; the loop's trough is a height field over the wall, so each point of the wall is
/// under one prism).

#include <optional>
#include <vector>

#include "simulator/camera/surface_bvh.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/dynamics/cavity_pressure.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// The deepest point of one sweep in the wall.
struct WallCut {
  double depth = 0.0;      ///< m below the cavity's surface
  double thickness = 0.0;  ///< m, the wall's thickness there
  bool perforated = false;
  double removed_volume = 0.0;  ///< m³ of wall between the swept surface and the cavity's
};

class WallCutGauge {
 public:
  /// The wall is body `body` of the world, with `cavity` its cavity surface (on its nodes).
  WallCutGauge(int body, CavitySurface cavity);

  /// The deepest point of `swept` (m, at the world's current positions) in the wall; nullopt
  /// when the sweep stayed in the cavity.
  std::optional<WallCut> measure(const World& world, const cutting::CutSurface& swept) const;

  int body() const { return body_; }

 private:
  int body_;
  CavitySurface cavity_;
};

}  // namespace viscera::sim
