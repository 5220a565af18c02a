#pragma once
/// The growing tree of CCO (cco_vessel_generator.h) and its Poiseuille hydraulics (Karch et al.
/// 1999, §2): every subtree keeps its reduced resistance, volume factor and terminal count, so
/// inserting a terminal updates only the path to the root, and a trial insertion is evaluated
/// without changing anything. Internal to the generator.

#include <vector>

#include "core/math_types.h"
#include "templates/vessels/cco_vessel_generator.h"

namespace viscera::templates::cco {

using core::Vec3;

/// Hydraulic summary of a subtree: reduced resistance R* = R·r⁴ of the subtree with its root
/// segment's radius factored out (Pa·s·m), volume factor S with V = π r² S (m), terminal count.
struct Summary {
  double resistance = 0.0;
  double volume_factor = 0.0;
  int terminals = 1;
};

/// One segment of the growing tree (a node and the segment that feeds it).
struct Node {
  Vec3 proximal = Vec3::Zero(), distal = Vec3::Zero();
  int parent = -1, left = -1, right = -1;
  Summary summary;
  double beta_left = 0.0, beta_right = 0.0;  ///< child radius / own radius
  bool alive = true;
  int birth = 0;  ///< insertion order of the terminal that created it
};

/// The tree while it grows, with Poiseuille hydraulics kept up to date along changed paths.
/// Segments form a binary tree: a node has no children or two.
class GrowingTree {
 public:
  /// terminal_flow: m³/s drained by every terminal of the final tree.
  GrowingTree(const CcoOptions& options, double terminal_flow);

  std::vector<Node> nodes;
  int root = -1;

  /// Summary of a terminal segment.
  Summary leaf(double length, int terminals = 1) const;
  /// Summary of a segment of `length` whose children are `l` and `r`; sets the radius ratios
  /// (equal terminal pressures: (r_l/r_r)⁴ = Q_l R*_l / (Q_r R*_r); Murray: β_l^γ + β_r^γ = 1).
  Summary combine(double length, const Summary& l, const Summary& r, double& beta_l,
                  double& beta_r) const;
  /// Root radius that drives the subtree's flow through the pressure drop, in m.
  double root_radius(const Summary& s) const;

  /// Recomputes node i from its children; refresh_upwards also does all its ancestors.
  void refresh(int i);
  void refresh_upwards(int i);

  struct Trial {
    double volume = 0.0;           ///< m³ of the whole tree
    double terminal_radius = 0.0;  ///< m of the new terminal
  };
  /// Tree volume and new terminal radius if x were joined to segment j at bifurcation b;
  /// nothing changes (O(depth)).
  Trial try_insertion(int j, const Vec3& b, const Vec3& x) const;
  /// Joins x to segment j at b; returns the new terminal's index.
  int insert(int j, const Vec3& b, const Vec3& x, int birth);
  /// Removes terminal t and merges its parent with the sibling.
  void remove_terminal(int t);
  /// Radius of every alive node, top-down from the root.
  std::vector<double> radii() const;

  double terminal_flow() const { return terminal_flow_; }

 private:
  double viscous_factor_, gamma_, terminal_flow_, pressure_drop_;
};

}  // namespace viscera::templates::cco
