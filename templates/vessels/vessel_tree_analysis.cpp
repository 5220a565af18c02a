#include "templates/vessels/vessel_tree_analysis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "core/error.h"

namespace viscera::templates {
namespace {

/// Segments joined by less than this many radii sums of tree are parts of one junction: at a
/// branching angle θ the daughters' walls leave the parent's only (r_a + r_b)/sin θ along the
/// branch, which is 2 (r_a + r_b) at 30°.
constexpr double kJunctionZone = 2.0;

std::string segment_pointer(std::size_t i, const char* member) {
  return "/segments/" + std::to_string(i) + "/" + member;
}

}  // namespace

std::vector<std::vector<int>> segment_children(const core::VesselTree& tree) {
  std::vector<std::vector<int>> children(tree.segments.size());
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const int parent = tree.segments[i].parent;
    if (parent < -1 || parent >= static_cast<int>(i)) {
      throw core::ValidationError(
          "parent " + std::to_string(parent) + " must be -1 or an earlier segment",
          {"", segment_pointer(i, "parent"), tree.id});
    }
    if (parent >= 0) children[parent].push_back(static_cast<int>(i));
  }
  return children;
}

double segment_length(const core::VesselSegment& s) {
  return (s.distal - s.proximal).norm();
}

int terminal_count(const core::VesselTree& tree) {
  const auto children = segment_children(tree);
  return static_cast<int>(
      std::count_if(children.begin(), children.end(), [](const auto& c) { return c.empty(); }));
}

double tree_volume(const core::VesselTree& tree) {
  double volume = 0.0;
  for (const auto& s : tree.segments)
    volume += std::numbers::pi * s.radius * s.radius * segment_length(s);
  return volume;
}

double murray_deviation(const core::VesselTree& tree, double exponent) {
  const auto children = segment_children(tree);
  double worst = 0.0;
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    if (children[i].empty()) continue;
    const double parent = std::pow(tree.segments[i].radius, exponent);
    double sum = 0.0;
    for (const int c : children[i])
      sum += std::pow(tree.segments[c].radius, exponent);
    worst = std::max(worst, std::abs(parent - sum) / parent);
  }
  return worst;
}

double segment_distance(const core::Vec3& p1, const core::Vec3& q1, const core::Vec3& p2,
                        const core::Vec3& q2) {
  const core::Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  constexpr double kTiny = 1e-30;
  if (a <= kTiny && e <= kTiny) return r.norm();
  if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denominator = a * e - b * b;
      s = denominator > kTiny * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return ((p1 + s * d1) - (p2 + t * d2)).norm();
}

double tree_gap(const core::VesselTree& tree, int a, int b) {
  const auto& segs = tree.segments;
  // Ancestors of a with the length of the segments strictly between a and each of them.
  std::vector<std::pair<int, double>> up_a;
  double walked = 0.0;
  for (int k = a; k >= 0; k = segs[k].parent) {
    up_a.emplace_back(k, walked);
    if (k != a) walked += segment_length(segs[k]);
  }
  walked = 0.0;
  for (int k = b; k >= 0; k = segs[k].parent) {
    for (std::size_t i = 0; i < up_a.size(); ++i) {
      if (up_a[i].first != k) continue;
      if (i == 0) return walked;          // a is b or an ancestor of b
      if (k == b) return up_a[i].second;  // b is an ancestor of a
      return up_a[i].second + walked;     // different subtrees of k: they meet at k's far end
    }
    if (k != b) walked += segment_length(segs[k]);
  }
  return INFINITY;  // different roots
}

std::vector<std::pair<int, int>> find_intersections(const core::VesselTree& tree,
                                                    double clearance) {
  const auto& segs = tree.segments;
  const std::size_t n = segs.size();
  std::vector<std::pair<int, int>> hits;
  if (n < 2) return hits;
  core::BoundingBox box;
  double max_radius = 0.0, mean_extent = 0.0;
  for (const auto& s : segs) {
    box.add(s.proximal);
    box.add(s.distal);
    max_radius = std::max(max_radius, s.radius);
    mean_extent += segment_length(s) + 2.0 * s.radius;
  }
  // Cells about the size of an average segment; each segment is entered in every cell its
  // inflated box touches, so candidate pairs share a cell.
  const double cell = std::max(mean_extent / static_cast<double>(n), 1e-9);
  const core::Vec3 origin = box.min - core::Vec3::Constant(clearance * max_radius + cell);
  const auto cell_of = [&](double v, int axis) {
    return static_cast<long long>(std::floor((v - origin[axis]) / cell));
  };
  std::unordered_map<long long, std::vector<int>> grid;
  const auto key = [](long long x, long long y, long long z) {
    return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL);
  };
  std::vector<std::array<long long, 6>> ranges(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double pad = clearance * segs[i].radius;
    for (int a = 0; a < 3; ++a) {
      ranges[i][a] = cell_of(std::min(segs[i].proximal[a], segs[i].distal[a]) - pad, a);
      ranges[i][3 + a] = cell_of(std::max(segs[i].proximal[a], segs[i].distal[a]) + pad, a);
    }
    for (long long x = ranges[i][0]; x <= ranges[i][3]; ++x)
      for (long long y = ranges[i][1]; y <= ranges[i][4]; ++y)
        for (long long z = ranges[i][2]; z <= ranges[i][5]; ++z)
          grid[key(x, y, z)].push_back(static_cast<int>(i));
  }
  const auto adjacent = [&](int a, int b) {
    return tree_gap(tree, a, b) < kJunctionZone * (segs[a].radius + segs[b].radius);
  };
  std::vector<int> checked(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    for (long long x = ranges[i][0]; x <= ranges[i][3]; ++x)
      for (long long y = ranges[i][1]; y <= ranges[i][4]; ++y)
        for (long long z = ranges[i][2]; z <= ranges[i][5]; ++z) {
          const auto it = grid.find(key(x, y, z));
          if (it == grid.end()) continue;
          for (const int j : it->second) {
            if (j <= static_cast<int>(i) || checked[j] == static_cast<int>(i)) continue;
            checked[j] = static_cast<int>(i);
            if (adjacent(static_cast<int>(i), j)) continue;
            const double d = segment_distance(segs[i].proximal, segs[i].distal, segs[j].proximal,
                                              segs[j].distal);
            if (d < clearance * (segs[i].radius + segs[j].radius))
              hits.emplace_back(static_cast<int>(i), j);
          }
        }
  }
  std::sort(hits.begin(), hits.end());
  return hits;
}

std::vector<VesselTreeIssue> validate_vessel_tree(const core::VesselTree& tree,
                                                  double murray_tolerance) {
  std::vector<VesselTreeIssue> issues;
  if (tree.segments.empty()) {
    issues.push_back({"/segments", "a vessel tree needs at least one segment"});
    return issues;
  }
  std::vector<std::vector<int>> children;
  try {
    children = segment_children(tree);
  } catch (const core::ValidationError& e) {
    issues.push_back({e.location().json_pointer, e.reason()});
    return issues;
  }
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const auto& s = tree.segments[i];
    if (s.id != static_cast<int>(i))
      issues.push_back({segment_pointer(i, "id"), "ids must equal the segment index"});
    if (!s.proximal.allFinite() || !s.distal.allFinite() || !(segment_length(s) > 0.0)) {
      issues.push_back(
          {segment_pointer(i, "distal"), "a segment needs finite, distinct end points"});
    }
    if (!(s.radius > 0.0) || !std::isfinite(s.radius))
      issues.push_back({segment_pointer(i, "radius"), "radius must be positive"});
    if (!(s.flow > 0.0) || !std::isfinite(s.flow))
      issues.push_back({segment_pointer(i, "flow"), "flow must be positive"});
    if (s.parent >= 0 && (tree.segments[s.parent].distal - s.proximal).norm() >
                             1e-9 * std::max(1.0, s.proximal.norm())) {
      issues.push_back(
          {segment_pointer(i, "proximal"), "a child must start where its parent ends"});
    }
    if (!children[i].empty()) {
      double sum = 0.0;
      for (const int c : children[i])
        sum += tree.segments[c].flow;
      if (std::abs(sum - s.flow) > 0.01 * s.flow) {
        issues.push_back({segment_pointer(i, "flow"),
                          "flow differs from the sum of its children's by more than 1 %"});
      }
      double cubes = 0.0;
      for (const int c : children[i])
        cubes += std::pow(tree.segments[c].radius, 3.0);
      const double parent = std::pow(s.radius, 3.0);
      if (std::abs(parent - cubes) > murray_tolerance * parent) {
        issues.push_back({segment_pointer(i, "radius"),
                          "Murray's law r³ = Σ children r³ is off by " +
                              std::to_string(100.0 * std::abs(parent - cubes) / parent) + " %"});
      }
    }
  }
  for (const auto& [a, b] : find_intersections(tree)) {
    issues.push_back(
        {segment_pointer(a, "radius"), "segment intersects segment " + std::to_string(b)});
  }
  return issues;
}

void assign_murray_flows_and_radii(core::VesselTree& tree, double root_radius, double total_flow,
                                   const std::vector<double>& terminal_weights) {
  if (!(root_radius > 0.0) || !(total_flow > 0.0)) {
    throw core::UsageError("root radius and total flow must be positive");
  }
  const auto children = segment_children(tree);
  std::vector<int> terminals;
  for (std::size_t i = 0; i < children.size(); ++i) {
    if (children[i].empty()) terminals.push_back(static_cast<int>(i));
  }
  if (!terminal_weights.empty() && terminal_weights.size() != terminals.size()) {
    throw core::UsageError("one weight per terminal segment is needed");
  }
  double weight_sum = 0.0;
  for (std::size_t t = 0; t < terminals.size(); ++t) {
    const double w = terminal_weights.empty() ? 1.0 : terminal_weights[t];
    if (!(w > 0.0)) throw core::UsageError("terminal weights must be positive");
    weight_sum += w;
  }
  for (auto& s : tree.segments)
    s.flow = 0.0;
  for (std::size_t t = 0; t < terminals.size(); ++t) {
    tree.segments[terminals[t]].flow =
        total_flow * (terminal_weights.empty() ? 1.0 : terminal_weights[t]) / weight_sum;
  }
  // Children come after parents, so a reverse sweep adds every subtree before its parent.
  for (std::size_t i = tree.segments.size(); i-- > 0;) {
    for (const int c : children[i])
      tree.segments[i].flow += tree.segments[c].flow;
  }
  double root_flow = 0.0;
  for (const auto& s : tree.segments) {
    if (s.parent < 0) root_flow += s.flow;
  }
  for (auto& s : tree.segments)
    s.radius = root_radius * std::cbrt(s.flow / root_flow);
}

}  // namespace viscera::templates
