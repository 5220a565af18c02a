#include "templates/vessels/lsystem_vessel_tree.h"

#include <cmath>

#include "core/error.h"
#include "templates/vessels/vessel_tree_analysis.h"

namespace viscera::templates {

using core::Vec3;

core::VesselTree lsystem_vessel_tree(const core::Lsystem& grammar,
                                     const LsystemVesselOptions& options) {
  // Grammar lengths are in units of the turtle step: draw at unit scale, then scale to metres.
  core::TurtleOptions unit = options.turtle;
  unit.origin = Vec3::Zero();
  unit.step = 1.0;
  auto strokes = core::interpret_turtle(grammar.derive(options.generations, options.seed), unit);
  for (auto& s : strokes) {
    s.start = options.turtle.origin + options.turtle.step * s.start;
    s.end = options.turtle.origin + options.turtle.step * s.end;
  }
  core::VesselTree tree;
  tree.id = options.tree_id;
  tree.host_object = options.host_object;
  std::vector<int> segment_of(strokes.size(), -1);
  std::vector<double> end_width;
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const auto& s = strokes[i];
    if (!((s.end - s.start).norm() > 0.0)) continue;
    int parent = s.parent >= 0 ? segment_of[s.parent] : -1;
    // A stroke after an `f` move, or below a cut-off parent, does not continue its parent.
    if (s.parent >= 0 && parent < 0) continue;
    if (parent >= 0 &&
        (tree.segments[parent].distal - s.start).norm() > 1e-12 * (1.0 + s.start.norm())) {
      parent = -1;
    }
    if (options.domain && !(options.domain->contains(s.start) && options.domain->contains(s.end)))
      continue;
    core::VesselSegment segment;
    segment.id = static_cast<int>(tree.segments.size());
    segment.parent = parent;
    segment.proximal = s.start;
    segment.distal = s.end;
    segment_of[i] = segment.id;
    tree.segments.push_back(segment);
    end_width.push_back(std::max(s.end_width, 1e-12));
  }
  if (tree.segments.empty())
    throw core::InputError("the L-system draws no vessel inside the domain");
  for (int round = 0;; ++round) {
    const auto children = segment_children(tree);
    std::vector<double> weights;
    for (std::size_t i = 0; i < children.size(); ++i) {
      if (children[i].empty()) weights.push_back(std::pow(end_width[i], 3.0));
    }
    assign_murray_flows_and_radii(tree, options.root_radius, options.total_flow, weights);
    if (!options.prune_intersections) break;
    const auto hits = find_intersections(tree);
    if (hits.empty()) break;
    if (round > 1000) throw core::InputError("the L-system tree keeps crossing itself");
    // Cut the later branch of each touching pair, with its subtree (children come later, so
    // one forward sweep marks whole subtrees).
    std::vector<bool> cut(tree.segments.size(), false);
    for (const auto& hit : hits)
      cut[static_cast<std::size_t>(hit.second)] = true;
    for (std::size_t i = 0; i < tree.segments.size(); ++i) {
      if (tree.segments[i].parent >= 0 && cut[tree.segments[i].parent]) cut[i] = true;
    }
    core::VesselTree kept = tree;
    kept.segments.clear();
    std::vector<double> kept_width;
    std::vector<int> new_index(tree.segments.size(), -1);
    for (std::size_t i = 0; i < tree.segments.size(); ++i) {
      if (cut[i]) continue;
      core::VesselSegment s = tree.segments[i];
      new_index[i] = static_cast<int>(kept.segments.size());
      s.id = new_index[i];
      s.parent = s.parent >= 0 ? new_index[s.parent] : -1;
      kept.segments.push_back(s);
      kept_width.push_back(end_width[i]);
    }
    tree = std::move(kept);
    end_width = std::move(kept_width);
  }
  return tree;
}

}  // namespace viscera::templates
