#pragma once
/// The edges of one body that carry rest lengths — its Teschner distance terms (seed 000 §3) or
/// its KisMo springs (seed 001 §3.2) — as the terms that hold them give them, with the material
/// limits of each edge: plastic flow and tearing read and move them after a step.

#include <array>
#include <span>
#include <vector>

#include "simulator/dynamics/kismo_spring_term.h"
#include "simulator/dynamics/teschner_terms.h"

namespace viscera::sim {

/// True when an edge whose squared length is `squared` (m²) is certainly no longer than `limit`
/// (m): a test without a square root, leaving the exact comparison to the few edges within a
/// relative 5·10⁻¹⁰ of the limit or past it (so the exact test decides exactly as before).
inline bool certainly_within(double squared, double limit) {
  return squared <= limit * limit * (1.0 - 1e-9);
}

class BodyEdges {
 public:
  explicit BodyEdges(TeschnerDistanceTerm& distance) : distance_(&distance) {}
  explicit BodyEdges(KismoSpringTerm& springs) : springs_(&springs) {}

  /// Global node pairs.
  std::span<const std::array<int, 2>> edges() const;
  /// Rest lengths in m, writable.
  std::span<double> rest_lengths() const;
  const BodyModel& model() const;

  /// Per edge, the smallest value of `limit` (e.g. &core::Material::plastic_yield) over the
  /// materials of the tets that share it (wall layers meet at an edge: the weaker one rules);
  /// an edge in no tet takes the smallest over the body's materials. `first` is the body's
  /// first global node.
  std::vector<double> material_limit(double core::Material::*limit, int first) const;

 private:
  TeschnerDistanceTerm* distance_ = nullptr;
  KismoSpringTerm* springs_ = nullptr;
};

}  // namespace viscera::sim
