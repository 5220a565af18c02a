#pragma once
/// A uniform fluid pressure on an organ's cavity wall as nodal forces (seed 000 §2.1: "Pressure
/// is applied on the vertices inside the uterine cavity"). The cavity is the part of the
/// visual surface whose three vertices are marked in the "cavity" vertex attribute (the
/// hysteroscopy template marks the cavity and canal); each visual vertex rides on its body tet
/// through the embedding (or is body node v itself without one).
///
/// The traction of pressure P on a cavity triangle (a, b, c), outward normal n seen from the
/// tissue, is −P A n (the fluid pushes the wall away from the cavity); a third of it goes to
/// each corner, f = −P/6 (b − a) × (c − a), and from a visual vertex to its tet's nodes by the
/// embedding's barycentric weights. The load follows the current shape (a follower load).

#include <array>
#include <span>
#include <vector>

#include "core/scenario/scene_object.h"

namespace viscera::sim {

using core::Vec3;

/// The cavity wall of one organ in terms of its body nodes.
struct CavitySurface {
  std::vector<core::Triangle> faces;           ///< visual vertex indices, outward of tissue
  std::vector<std::array<int, 4>> nodes;       ///< per visual vertex: the body nodes it rides on
  std::vector<std::array<double, 4>> weights;  ///< per visual vertex: their weights (sum 1)

  bool empty() const { return faces.empty(); }
  /// Visual vertex v at body positions x, m.
  Vec3 vertex(std::span<const Vec3> x, int v) const;
};

/// The cavity of `object`: empty when its surface has no "cavity" marks (> 0.5) or no body.
CavitySurface cavity_surface(const core::SceneObject& object);

/// Adds the pressure load of `pressure` Pa on the cavity at body positions `x` (m) to `f` (N,
/// per body node).
void add_pressure_load(const CavitySurface& cavity, double pressure, std::span<const Vec3> x,
                       std::span<Vec3> f);

/// Volume (m³) the cavity's triangles enclose with `apex`: −⅙ Σ (a − o)·((b − o) × (c − o)),
/// positive for a pocket the tissue surrounds (the faces point into it). For a cavity open at
/// the canal, `apex` closes it (e.g. the cavity's rest centroid, kept fixed while comparing).
double cavity_volume(const CavitySurface& cavity, std::span<const Vec3> x, const Vec3& apex);

}  // namespace viscera::sim
