#include "templates/vessels/cco_vessel_generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "templates/vessels/cco_growing_tree.h"
#include "templates/vessels/vessel_tree_analysis.h"

namespace viscera::templates {
namespace {

using cco::GrowingTree;
using cco::Node;
using core::Vec3;

/// Bifurcation positions tried for a candidate segment P–D and new terminal x: points of the
/// triangle P, D, x near the segment, as fractions t along P–D and s towards x.
constexpr double kAlongSegment[] = {0.2, 0.35, 0.5, 0.65, 0.8};
constexpr double kTowardsTerminal[] = {0.0, 0.15, 0.3, 0.45};

/// Minimum length of a new segment in radii.
constexpr double kSlenderness = 3.0;

struct Candidate {
  double volume = 0.0;
  int segment = -1;
  Vec3 bifurcation = Vec3::Zero();
  double terminal_radius = 0.0;
};

class CcoGrower {
 public:
  CcoGrower(const PerfusionDomain& domain, const CcoOptions& o, int final_terminals)
      : domain_(domain),
        options_(o),
        tree_(o, o.perfusion_flow / final_terminals),
        rng_(o.seed),
        final_terminals_(final_terminals) {}

  void start(const Vec3& inlet, const Vec3* first_terminal) {
    Vec3 x = Vec3::Zero();
    if (first_terminal) {
      x = *first_terminal;
    } else {
      const double wanted = 0.25 * domain_.bounds().size().norm();
      for (int attempt = 0;; ++attempt) {
        x = domain_.random_point(rng_);
        if (((x - inlet).norm() > wanted * std::pow(0.9, attempt / 50) &&
             domain_.contains_segment(inlet, x)) ||
            attempt > 5000) {
          break;
        }
      }
    }
    Node root;
    root.proximal = inlet;
    root.distal = x;
    tree_.nodes.push_back(root);
    tree_.root = 0;
    tree_.refresh(0);
    radii_ = tree_.radii();
    terminals_ = 1;
  }

  /// Adds one terminal at a random admissible point, or at `fixed` when given.
  bool add_terminal(const Vec3* fixed) {
    const double v = domain_.volume();
    double threshold = 0.5 * std::cbrt(v / (terminals_ + 1));
    for (int attempt = 0; attempt < 20000; ++attempt) {
      if (attempt > 0 && attempt % 50 == 0) threshold *= 0.9;  // Karch: relax after failures
      const Vec3 x = fixed ? *fixed : domain_.random_point(rng_);
      if (!fixed && distance_to_tree(x) < threshold) continue;
      if (connect(x)) return true;
      if (fixed) return false;
    }
    return false;
  }

  /// Removes terminals whose walls touch others in the final geometry; returns how many.
  int remove_intersections() {
    const core::VesselTree tree = export_tree();
    const auto hits = find_intersections(tree, options_.clearance);
    if (hits.empty()) return 0;
    std::vector<int> doomed;
    for (const auto& [a, b] : hits) {
      // Drop the younger of the youngest terminals below the touching segments; when one segment
      // lies below the other, only terminals below the lower one can be what moved in.
      const int na = order_[a], nb = order_[b];
      const bool a_above_b = is_ancestor(na, nb), b_above_a = is_ancestor(nb, na);
      const int ta = youngest_terminal(na), tb = youngest_terminal(nb);
      if (a_above_b) {
        doomed.push_back(tb);
      } else if (b_above_a) {
        doomed.push_back(ta);
      } else {
        doomed.push_back(tree_.nodes[ta].birth >= tree_.nodes[tb].birth ? ta : tb);
      }
    }
    std::sort(doomed.begin(), doomed.end());
    doomed.erase(std::unique(doomed.begin(), doomed.end()), doomed.end());
    int removed = 0;
    for (const int t : doomed) {
      if (!tree_.nodes[t].alive || tree_.nodes[t].parent < 0) continue;
      tree_.remove_terminal(t);
      --terminals_;
      ++removed;
    }
    radii_ = tree_.radii();
    return removed;
  }

  int terminals() const { return terminals_; }

  core::VesselTree export_tree() {
    core::VesselTree tree;
    tree.id = options_.tree_id;
    tree.host_object = options_.host_object;
    tree.kind = "arterial";
    const auto radius = tree_.radii();
    order_.clear();
    std::vector<std::pair<int, int>> stack = {{tree_.root, -1}};
    while (!stack.empty()) {
      const auto [i, parent] = stack.back();
      stack.pop_back();
      const Node& n = tree_.nodes[i];
      core::VesselSegment s;
      s.id = static_cast<int>(tree.segments.size());
      s.parent = parent;
      s.proximal = n.proximal;
      s.distal = n.distal;
      s.radius = radius[i];
      s.flow = tree_.terminal_flow() * n.summary.terminals;
      tree.segments.push_back(s);
      order_.push_back(i);
      if (n.left >= 0) {
        stack.emplace_back(n.right, s.id);
        stack.emplace_back(n.left, s.id);
      }
    }
    return tree;
  }

 private:
  double distance_to_tree(const Vec3& x) const {
    double best = INFINITY;
    for (const auto& n : tree_.nodes) {
      if (n.alive) best = std::min(best, segment_distance(x, x, n.proximal, n.distal));
    }
    return best;
  }

  bool is_ancestor(int ancestor, int i) const {
    for (int k = tree_.nodes[i].parent; k >= 0; k = tree_.nodes[k].parent) {
      if (k == ancestor) return true;
    }
    return false;
  }

  int youngest_terminal(int i) const {
    int best = -1;
    std::vector<int> stack = {i};
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      const Node& n = tree_.nodes[k];
      if (n.left < 0) {
        if (n.parent >= 0 && (best < 0 || n.birth > tree_.nodes[best].birth)) best = k;
      } else {
        stack.push_back(n.left);
        stack.push_back(n.right);
      }
    }
    return best < 0 ? i : best;
  }

  /// Radii still grow as terminals are added: a segment's flow scales with the terminals it will
  /// feed, and by Murray's law its radius with the flow's cube root. Constraints use radii
  /// projected to the final tree, (final / current terminals)^(1/3) times today's.
  double projection() const {
    return std::cbrt(static_cast<double>(final_terminals_) / std::max(terminals_, 1));
  }

  bool intersects(const Vec3& b, const Vec3& x, double radius, int joined) const {
    const double grow = projection();
    for (std::size_t k = 0; k < tree_.nodes.size(); ++k) {
      const Node& n = tree_.nodes[k];
      // The joined segment is split at b and shares that node with the new terminal; its
      // children start at the continuation's far end, so they are checked like any other.
      if (!n.alive || static_cast<int>(k) == joined) continue;
      const double d = segment_distance(b, x, n.proximal, n.distal);
      if (d < options_.clearance * grow * (radius + radii_[k])) return true;
    }
    return false;
  }

  /// Splitting segment j at b makes pairs that shared a node strangers: j's children no longer
  /// touch the proximal part P–b, and j's parent and sibling no longer touch the distal part
  /// b–D. Those pairs must keep their walls apart too.
  bool split_touches(int j, const Vec3& b) const {
    const Node& J = tree_.nodes[j];
    const double r = radii_[j], grow = projection();
    const auto apart = [&](int k, const Vec3& p, const Vec3& q) {
      const Node& n = tree_.nodes[k];
      return segment_distance(p, q, n.proximal, n.distal) >=
             options_.clearance * grow * (r + radii_[k]);
    };
    if (J.left >= 0 && (!apart(J.left, J.proximal, b) || !apart(J.right, J.proximal, b)))
      return true;
    if (J.parent >= 0) {
      const Node& P = tree_.nodes[J.parent];
      const int sibling = P.left == j ? P.right : P.left;
      if (!apart(J.parent, b, J.distal) || !apart(sibling, b, J.distal)) return true;
    }
    return false;
  }

  bool connect(const Vec3& x) {
    // The nearest segments by centre-line distance.
    std::vector<std::pair<double, int>> nearest;
    for (std::size_t k = 0; k < tree_.nodes.size(); ++k) {
      const Node& n = tree_.nodes[k];
      if (n.alive)
        nearest.emplace_back(segment_distance(x, x, n.proximal, n.distal), static_cast<int>(k));
    }
    const std::size_t keep = std::min<std::size_t>(
        nearest.size(), static_cast<std::size_t>(options_.candidate_segments));
    std::partial_sort(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(keep),
                      nearest.end());
    nearest.resize(keep);
    std::vector<Candidate> candidates;
    for (const auto& [distance, j] : nearest) {
      const Node& J = tree_.nodes[j];
      for (const double t : kAlongSegment) {
        const Vec3 on_segment = J.proximal + t * (J.distal - J.proximal);
        for (const double s : kTowardsTerminal) {
          const Vec3 b = on_segment + s * (x - on_segment);
          const auto trial = tree_.try_insertion(j, b, x);
          candidates.push_back({trial.volume, j, b, trial.terminal_radius});
        }
      }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return a.volume < b.volume || (a.volume == b.volume && a.segment < b.segment);
    });
    for (const auto& c : candidates) {
      // Every segment the insertion creates must be slender (length ≥ 3 projected radii): a
      // stub shorter than its radius puts the walls of the segments around it in contact.
      const Node& J = tree_.nodes[c.segment];
      const double r = radii_[c.segment] * projection();
      if ((x - c.bifurcation).norm() < kSlenderness * c.terminal_radius * projection() ||
          (c.bifurcation - J.proximal).norm() < kSlenderness * r ||
          (J.distal - c.bifurcation).norm() < kSlenderness * r) {
        continue;
      }
      if (intersects(c.bifurcation, x, c.terminal_radius, c.segment)) continue;
      if (split_touches(c.segment, c.bifurcation)) continue;
      if (!domain_.contains_segment(c.bifurcation, x)) continue;
      tree_.insert(c.segment, c.bifurcation, x, ++births_);
      radii_ = tree_.radii();
      ++terminals_;
      return true;
    }
    return false;
  }

  const PerfusionDomain& domain_;
  const CcoOptions& options_;
  GrowingTree tree_;
  core::Rng rng_;
  std::vector<double> radii_;
  std::vector<int> order_;  ///< node index of each exported segment
  int terminals_ = 0;
  int births_ = 0;
  int final_terminals_ = 1;
};

}  // namespace

core::VesselTree grow_cco_tree(const PerfusionDomain& domain, const CcoOptions& options,
                               core::Progress& progress) {
  const bool fixed = !options.perfusion_points.empty();
  const int wanted = fixed ? static_cast<int>(options.perfusion_points.size()) : options.terminals;
  if (wanted < 1 || wanted > 100000)
    throw core::UsageError("terminals must be between 1 and 100000");
  if (!(options.perfusion_flow > 0.0) || !(options.viscosity > 0.0) ||
      !(options.perfusion_pressure > options.terminal_pressure) ||
      !(options.murray_exponent >= 2.0) || !(options.murray_exponent <= 3.5) ||
      options.candidate_segments < 1 || !(options.clearance >= 0.0)) {
    throw core::UsageError(
        "CCO needs positive flow and viscosity, perfusion pressure above terminal pressure, "
        "a Murray exponent in [2, 3.5], at least one candidate segment and a non-negative "
        "clearance");
  }
  const Vec3 inlet = options.inlet ? *options.inlet : domain.default_inlet();
  if (!domain.contains(inlet)) throw core::UsageError("the inlet lies outside the domain");
  for (std::size_t i = 0; i < options.perfusion_points.size(); ++i) {
    if (!domain.contains(options.perfusion_points[i])) {
      throw core::UsageError("perfusion point " + std::to_string(i) + " lies outside the domain");
    }
  }

  progress.begin_stage("growing vessel tree", wanted);
  CcoGrower grower(domain, options, wanted);
  grower.start(inlet, fixed ? &options.perfusion_points[0] : nullptr);
  progress.step();
  std::size_t next_fixed = 1;
  for (int repair = 0;; ++repair) {
    while (grower.terminals() < wanted) {
      const Vec3* point = fixed ? &options.perfusion_points[next_fixed] : nullptr;
      if (!grower.add_terminal(point)) {
        throw core::InputError(fixed ? "perfusion point " + std::to_string(next_fixed) +
                                           " cannot be joined without crossing another vessel"
                                     : "the domain has no room for " + std::to_string(wanted) +
                                           " terminals at this vessel size");
      }
      if (fixed) ++next_fixed;
      progress.step();
    }
    // Radii settle only when the tree is complete; touching walls are removed and regrown.
    if (grower.remove_intersections() == 0) break;
    if (fixed || repair > 50) {
      throw core::InputError(
          "vessel walls keep touching; try fewer terminals or a smaller clearance");
    }
  }
  return grower.export_tree();
}

}  // namespace viscera::templates
