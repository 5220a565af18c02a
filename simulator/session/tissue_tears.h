#pragma once
/// Tissue torn apart (issue 17 §4; seed 001 §4.1: "is the amount of force acting on a mass knot
/// bigger than a threshold value, so the object topology is changed by duplicating mass knots
/// and springs properly to simulate tearing apart of the virtual soft tissue").
///
/// The TissueTearing terms record each link stretched past its material's tearing threshold
/// (dynamics/tissue_tearing.h). On the bodies a session can cut, each new tear here becomes a
/// crack: a planar hybrid cut (seed 000 §5.1) through the torn link's midpoint, across it (its
/// normal along the link), a square twice the link's current length on a side. The cut splits
/// the link and separates the knots on the crack — the seed's knot duplication, with the
/// neighbouring tets divided as the hybrid cut divides them — and the world takes the new
/// topology (World::topology_changed), so the load passes to the links at the crack's rim,
/// which tear in turn while the pull lasts.
///
/// Decided where the seed is silent: which links go with a duplicated knot is the crack
/// plane's side; the crack's own new links (those with a knot the crack made) and a link
/// already split are not split again, so a crack does not refine itself step after step; a
/// tear whose crack would cut nothing (the hybrid cut's quality gate snapped it away) stays a
/// recorded tear only. The uterine wall is not among the bodies (its hydrometra states are per
/// node, and perforation has its own rules).

#include <cstdint>
#include <functional>
#include <set>
#include <utility>
#include <vector>

#include "simulator/cutting/topology_change.h"
#include "simulator/session/session_report.h"
#include "simulator/session/visible_surfaces.h"
#include "simulator/world/world.h"

namespace viscera::sim {

class TissueTears {
 public:
  /// `bodies`: the world bodies that tear apart (those the session's instrument can cut).
  TissueTears(const World& world, std::vector<int> bodies);

  /// Told of each crack after the world took its new topology (the session starts bleeding
  /// there).
  using CrackObserver =
      std::function<void(int body, const cutting::TopologyChange& change, double time)>;
  void on_crack(CrackObserver observer) { observer_ = std::move(observer); }
  /// Cracks go through `surfaces` (null: the tets alone), so the visible surfaces follow.
  void cut_visible_surfaces(VisibleSurfaces* surfaces) { visible_ = surfaces; }

  /// After every step: splits the tears recorded since the last call, at `time` s; each crack
  /// is a "tissue-torn-apart" event.
  void follow(World& world, double time, std::vector<SessionEvent>& events);

 private:
  bool tears(int body) const;

  std::vector<int> bodies_;
  std::size_t seen_ = 0;  ///< tears of the world's terms handled so far
  /// Per world body: 1 for nodes a crack made (their links are the crack's own).
  std::vector<std::vector<std::uint8_t>> made_by_crack_;
  std::set<std::pair<int, std::pair<int, int>>> split_;  ///< (body, link) already split
  VisibleSurfaces* visible_ = nullptr;
  CrackObserver observer_;
};

}  // namespace viscera::sim
