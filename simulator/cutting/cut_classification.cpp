#include "simulator/cutting/cut_classification.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace viscera::sim::cutting {
namespace {

using core::Tetrahedron;
using core::Vec3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

class Classifier {
 public:
  Classifier(const core::TetMesh& body, const std::vector<Vec3>& current,
             const CutSurfaceIndex& index, const ClassificationOptions& options)
      : body_(body), x_(current), index_(index), options_(options) {
    max_cos_ = std::cos(options.min_dihedral_degrees * M_PI / 180.0);
  }

  CutClassification run() {
    find_candidates();
    if (candidates_.empty()) return std::move(c_);
    find_crossings();
    for (;;) {
      make_consistent();
      if (!enforce_quality()) break;
    }
    finish();
    return std::move(c_);
  }

 private:
  // Tets whose box of grid cells holds a triangle of the cut surface. A tet with all corners
  // beyond one face of the surface's box (per-node outcodes, Cohen–Sutherland) is out at once;
  // for the others each node's cell is found once and a tet's cells span its corners' cells.
  void find_candidates() {
    const std::size_t n = body_.nodes.size();
    std::vector<std::uint8_t> outcode(n, 0);
    std::vector<std::array<int, 3>> cell(n);
    for (std::size_t v = 0; v < n; ++v) {
      outcode[v] = index_.outcode(x_[v]);
      cell[v] = index_.cell_of(x_[v]);
    }
    double edge_sum = 0.0;
    for (int t = 0; t < static_cast<int>(body_.tets.size()); ++t) {
      const Tetrahedron& tet = body_.tets[t];
      if (outcode[tet[0]] & outcode[tet[1]] & outcode[tet[2]] & outcode[tet[3]]) continue;
      std::array<int, 3> lo = cell[tet[0]], hi = lo;
      for (int k = 1; k < 4; ++k) {
        for (int d = 0; d < 3; ++d) {
          lo[d] = std::min(lo[d], cell[tet[k]][d]);
          hi[d] = std::max(hi[d], cell[tet[k]][d]);
        }
      }
      if (!index_.cells_hold_triangle(lo, hi)) continue;
      candidates_.push_back(t);
      core::BoundingBox box;
      for (int v : tet)
        box.add(x_[v]);
      edge_sum += box.size().norm();
      if (index_.triangle_may_meet(lo, hi, box)) met_.push_back(t);
    }
    if (!candidates_.empty()) search_radius_ = 2.0 * edge_sum / candidates_.size();
  }

  // The edges of the candidate tets the surface may meet, each once, in key order: grouped by
  // their lower node (a counting sort), then sorted within the group. An edge of other tets
  // only lies in boxes no triangle meets, so it cannot cross.
  std::vector<std::uint64_t> candidate_edges() const {
    const std::size_t n = body_.nodes.size();
    std::vector<int> offset(n + 1, 0);
    for (int t : met_) {
      const Tetrahedron& tet = body_.tets[t];
      for (const auto& e : kTetEdges)
        ++offset[std::min(tet[e[0]], tet[e[1]]) + 1];
    }
    for (std::size_t v = 0; v < n; ++v)
      offset[v + 1] += offset[v];
    std::vector<int> upper(offset[n]), fill(offset.begin(), offset.end() - 1);
    for (int t : met_) {
      const Tetrahedron& tet = body_.tets[t];
      for (const auto& e : kTetEdges) {
        const int a = std::min(tet[e[0]], tet[e[1]]), b = std::max(tet[e[0]], tet[e[1]]);
        upper[fill[a]++] = b;
      }
    }
    std::vector<std::uint64_t> edges;
    edges.reserve(upper.size() / 2);
    for (std::size_t a = 0; a < n; ++a) {
      const auto begin = upper.begin() + offset[a], end = upper.begin() + offset[a + 1];
      std::sort(begin, end);
      for (auto it = begin; it != end; ++it) {
        if (it == begin || *it != *(it - 1)) edges.push_back(edge_key(static_cast<int>(a), *it));
      }
    }
    return edges;
  }

  void find_crossings() {
    const std::size_t n = body_.nodes.size();
    c_.side.assign(n, kUnknownSide);
    distance_.assign(n, std::numeric_limits<double>::quiet_NaN());
    std::vector<std::uint8_t> plus(n, 0), minus(n, 0), snapped(n, 0);
    std::vector<std::pair<std::uint64_t, SegmentCrossing>> crossed;
    for (std::uint64_t key : candidate_edges()) {
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      if (const auto hit = index_.crossing(x_[a], x_[b])) crossed.emplace_back(key, *hit);
    }
    const double snap = options_.snap_fraction;
    for (const auto& [key, hit] : crossed) {
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      const auto vote = [&](int node, int s) { (s > 0 ? plus : minus)[node] = 1; };
      if (hit.t < snap) {
        snapped[a] = 1;
        vote(b, hit.direction);
      } else if (hit.t > 1.0 - snap) {
        snapped[b] = 1;
        vote(a, -hit.direction);
      } else {
        vote(a, -hit.direction);
        vote(b, hit.direction);
        c_.hits.emplace(key, EdgeHit{hit.t, hit.direction});
      }
    }
    for (int t : candidates_) {
      for (int v : body_.tets[t]) {
        if (c_.side[v] != kUnknownSide) continue;
        if (snapped[v] || (plus[v] && minus[v])) {
          c_.side[v] = 0;
        } else if (plus[v]) {
          c_.side[v] = 1;
        } else if (minus[v]) {
          c_.side[v] = -1;
        }
      }
    }
  }

  double distance_to_cut(int node) {
    if (std::isnan(distance_[node])) {
      const auto near = index_.nearest(x_[node], search_radius_);
      distance_[node] = near ? near->distance : kInfinity;
    }
    return distance_[node];
  }

  void snap(int node) {
    c_.side[node] = 0;
    newly_snapped_.push_back(node);
  }

  // Makes every candidate tet's corner sides agree with its cut edges: a corner the cut does
  // not reach gets its side from the surface's normal, and two corners on opposite sides of an
  // edge the surface does not cross (the cut's border passes between them) are resolved by
  // snapping the one nearer the surface.
  void make_consistent() {
    bool changed = true;
    while (changed) {
      changed = false;
      for (int t : candidates_) {
        const Tetrahedron& tet = body_.tets[t];
        bool has_cut = false;
        for (const auto& e : kTetEdges) {
          has_cut = has_cut || c_.side[tet[e[0]]] * c_.side[tet[e[1]]] == -1;
        }
        if (!has_cut) continue;
        for (int v : tet) {
          if (c_.side[v] != kUnknownSide) continue;
          const auto near = index_.nearest(x_[v], search_radius_);
          if (near && std::abs(near->signed_distance) > 1e-12) {
            c_.side[v] = near->signed_distance > 0 ? 1 : -1;
          } else {
            snap(v);
          }
          changed = true;
        }
        for (const auto& e : kTetEdges) {
          const int a = tet[e[0]], b = tet[e[1]];
          if (c_.side[a] * c_.side[b] != -1 || c_.hits.count(edge_key(a, b))) continue;
          snap(distance_to_cut(a) <= distance_to_cut(b) ? a : b);
          changed = true;
        }
      }
    }
  }

  // Decomposes every tet with a cut edge and snaps, for any child below the quality bound in
  // either configuration, the parent's cut corner nearest the surface. Returns true when it
  // snapped (the caller then re-runs the consistency pass and this check).
  bool enforce_quality() {
    std::vector<std::uint8_t> dirty_node;
    if (checked_once_) {
      if (newly_snapped_.empty()) return false;
      dirty_node.assign(body_.nodes.size(), 0);
      for (int v : newly_snapped_)
        dirty_node[v] = 1;
    }
    newly_snapped_.clear();
    const int n = static_cast<int>(body_.nodes.size());
    for (int t : candidates_) {
      const Tetrahedron& tet = body_.tets[t];
      if (checked_once_ &&
          !(dirty_node[tet[0]] || dirty_node[tet[1]] || dirty_node[tet[2]] || dirty_node[tet[3]])) {
        continue;
      }
      const TetCutPattern pattern = pattern_of(c_, tet, n);
      bool any_cut = false;
      for (bool cut : pattern.edge_cut)
        any_cut = any_cut || cut;
      if (!any_cut) continue;
      if (children_fit(tet, pattern)) continue;
      int worst = -1;
      double nearest = kInfinity;
      for (int e = 0; e < 6; ++e) {
        if (!pattern.edge_cut[e]) continue;
        for (int corner : kTetEdges[e]) {
          const double d = distance_to_cut(tet[corner]);
          if (worst < 0 || d < nearest) worst = tet[corner], nearest = d;
        }
      }
      snap(worst);
    }
    checked_once_ = true;
    return !newly_snapped_.empty();
  }

  bool children_fit(const Tetrahedron& tet, const TetCutPattern& pattern) const {
    std::array<Vec3, 10> cur, rest;
    for (int i = 0; i < 4; ++i)
      cur[i] = x_[tet[i]], rest[i] = body_.nodes[tet[i]];
    for (int e = 0; e < 6; ++e) {
      if (!pattern.edge_cut[e]) continue;
      const int a = tet[kTetEdges[e][0]], b = tet[kTetEdges[e][1]];
      cur[4 + e] = edge_point(c_, x_, a, b);
      rest[4 + e] = edge_point(c_, body_.nodes, a, b);
    }
    for (auto child : decompose(pattern)) {
      if (core::signed_volume(cur[child[0]], cur[child[1]], cur[child[2]], cur[child[3]]) < 0) {
        std::swap(child[2], child[3]);
      }
      if (!tet_is_fit(cur[child[0]], cur[child[1]], cur[child[2]], cur[child[3]], max_cos_) ||
          !tet_is_fit(rest[child[0]], rest[child[1]], rest[child[2]], rest[child[3]], max_cos_)) {
        return false;
      }
    }
    return true;
  }

  void finish() {
    std::vector<std::uint8_t> seen(body_.nodes.size(), 0);
    for (int t : candidates_) {
      const Tetrahedron& tet = body_.tets[t];
      bool touched = false;
      for (int v : tet) {
        touched = touched || c_.side[v] == 0;
        if (c_.side[v] == 0 && !seen[v]) seen[v] = 1, ++c_.snapped;
      }
      for (const auto& e : kTetEdges) {
        const int a = tet[e[0]], b = tet[e[1]];
        if (c_.side[a] * c_.side[b] != -1) continue;
        touched = true;
        if (a < b)
          c_.cut_edges.push_back(edge_key(a, b));
        else
          c_.cut_edges.push_back(edge_key(b, a));
      }
      if (touched) c_.traversed.push_back(t);
    }
    std::sort(c_.cut_edges.begin(), c_.cut_edges.end());
    c_.cut_edges.erase(std::unique(c_.cut_edges.begin(), c_.cut_edges.end()), c_.cut_edges.end());
  }

  const core::TetMesh& body_;
  const std::vector<Vec3>& x_;
  const CutSurfaceIndex& index_;
  ClassificationOptions options_;
  double max_cos_ = 1.0;
  double search_radius_ = 0.0;
  std::vector<int> candidates_;
  std::vector<int> met_;  ///< candidates a triangle may meet
  std::vector<double> distance_;
  std::vector<int> newly_snapped_;
  bool checked_once_ = false;
  CutClassification c_;
};

}  // namespace

bool is_cut(const CutClassification& c, int a, int b) {
  return c.side[a] * c.side[b] == -1;
}

TetCutPattern pattern_of(const CutClassification& c, const Tetrahedron& tet, int /*node_count*/) {
  TetCutPattern p;
  for (int i = 0; i < 4; ++i) {
    const int s = c.side[tet[i]];
    p.side[i] = (s == kUnknownSide) ? 0 : s;  // unknown corners only occur in uncut tets
    p.rank[i] = static_cast<std::uint64_t>(tet[i]);
  }
  for (int e = 0; e < 6; ++e) {
    const int a = tet[kTetEdges[e][0]], b = tet[kTetEdges[e][1]];
    p.edge_cut[e] = is_cut(c, a, b);
    p.rank[4 + e] = (std::uint64_t{1} << 62) + edge_key(a, b);
  }
  return p;
}

Vec3 edge_point(const CutClassification& c, const std::vector<Vec3>& x, int a, int b) {
  const int lo = std::min(a, b), hi = std::max(a, b);
  const double t = c.hits.at(edge_key(lo, hi)).t;
  return (1.0 - t) * x[lo] + t * x[hi];
}

bool tet_is_fit(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                double max_cos_dihedral) {
  if (core::signed_volume(a, b, c, d) <= 0.0) return false;
  // Outward face normals; the dihedral angle at the edge of faces i and j has cos = −ni·nj.
  const Vec3 n[4] = {(c - b).cross(d - b), (d - a).cross(c - a), (b - a).cross(d - a),
                     (c - a).cross(b - a)};
  Vec3 u[4];
  for (int i = 0; i < 4; ++i) {
    const double len = n[i].norm();
    if (!(len > 0.0)) return false;
    u[i] = n[i] / len;
  }
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      if (-u[i].dot(u[j]) > max_cos_dihedral) return false;
    }
  }
  return true;
}

double max_cos_dihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (core::signed_volume(a, b, c, d) <= 0.0) return 1.0;
  const Vec3 n[4] = {(c - b).cross(d - b), (d - a).cross(c - a), (b - a).cross(d - a),
                     (c - a).cross(b - a)};
  double length[4];
  for (int i = 0; i < 4; ++i) {
    length[i] = n[i].norm();
    if (!(length[i] > 0.0)) return 1.0;
  }
  double max_cos = -1.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j)
      max_cos = std::max(max_cos, -n[i].dot(n[j]) / (length[i] * length[j]));
  }
  return std::min(max_cos, 1.0);
}

double dihedral_degrees(double cos_dihedral) {
  return std::acos(std::clamp(cos_dihedral, -1.0, 1.0)) * 180.0 / M_PI;
}

double min_dihedral_degrees(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dihedral_degrees(max_cos_dihedral(a, b, c, d));
}

CutClassification classify_cut(const core::TetMesh& body, const std::vector<Vec3>& current,
                               const CutSurfaceIndex& index, const ClassificationOptions& options) {
  return Classifier(body, current, index, options).run();
}

}  // namespace viscera::sim::cutting
