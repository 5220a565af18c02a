#include "simulator/collision/penetration_depth.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace viscera::sim {
namespace {

/// Heidelberger et al. 2004 weight the contributions by inverse squared distance; the floor
/// keeps a point lying exactly on the surface finite.
double weight(const core::Vec3& a, const core::Vec3& b) {
  return 1.0 / std::max((a - b).squaredNorm(), 1e-18);
}

/// Surface triangles bucketed by the grid cells their boxes cover, for segment queries.
class TriangleGrid {
 public:
  /// Only triangles whose boxes meet `region` are kept: the segments to test lie inside it,
  /// and a contact touches a small part of a large surface.
  TriangleGrid(const PenetratedSurface& surface, const core::BoundingBox& region) {
    std::vector<int> kept;
    double edge_sum = 0.0;
    for (std::size_t t = 0; t < surface.faces.size(); ++t) {
      const auto& f = surface.faces[t];
      core::BoundingBox box;
      for (const int v : f)
        box.add(surface.positions[v]);
      if ((box.max.array() < region.min.array()).any() ||
          (box.min.array() > region.max.array()).any())
        continue;
      kept.push_back(static_cast<int>(t));
      edge_sum += (surface.positions[f[1]] - surface.positions[f[0]]).norm();
    }
    cell_ = kept.empty() ? 1.0 : std::max(edge_sum / static_cast<double>(kept.size()), 1e-9);
    for (const int t : kept) {
      core::BoundingBox box;
      for (const int v : surface.faces[t])
        box.add(surface.positions[v]);
      visit_cells(box, [&](const Key& key) { cells_[key].push_back(t); });
    }
  }

  /// Triangles whose boxes share a cell with the box of segment p→q, sorted and unique.
  std::vector<int> candidates(const core::Vec3& p, const core::Vec3& q) const {
    core::BoundingBox box;
    box.add(p);
    box.add(q);
    std::vector<int> found;
    visit_cells(box, [&](const Key& key) {
      if (const auto it = cells_.find(key); it != cells_.end())
        found.insert(found.end(), it->second.begin(), it->second.end());
    });
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }

 private:
  using Key = std::array<std::int64_t, 3>;

  template <typename Visit>
  void visit_cells(const core::BoundingBox& box, Visit&& visit) const {
    const auto lo = (box.min / cell_).array().floor().cast<std::int64_t>();
    const auto hi = (box.max / cell_).array().floor().cast<std::int64_t>();
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
          visit(Key{i, j, k});
  }

  double cell_ = 1.0;
  std::map<Key, std::vector<int>> cells_;
};

}  // namespace

VertexAdjacency VertexAdjacency::from_edges(std::size_t vertex_count,
                                            std::span<const std::array<int, 2>> edges) {
  VertexAdjacency adjacency;
  adjacency.offsets.assign(vertex_count + 1, 0);
  for (const auto& [a, b] : edges) {
    ++adjacency.offsets[a + 1];
    ++adjacency.offsets[b + 1];
  }
  for (std::size_t v = 0; v < vertex_count; ++v)
    adjacency.offsets[v + 1] += adjacency.offsets[v];
  adjacency.neighbours.resize(adjacency.offsets.back());
  std::vector<int> fill(adjacency.offsets.begin(), adjacency.offsets.end() - 1);
  for (const auto& [a, b] : edges) {
    adjacency.neighbours[fill[a]++] = b;
    adjacency.neighbours[fill[b]++] = a;
  }
  for (std::size_t v = 0; v < vertex_count; ++v) {
    std::sort(adjacency.neighbours.begin() + adjacency.offsets[v],
              adjacency.neighbours.begin() + adjacency.offsets[v + 1]);
  }
  return adjacency;
}

VertexAdjacency VertexAdjacency::from_tets(std::size_t vertex_count,
                                           std::span<const std::array<int, 4>> tets) {
  // Every tet lists its three other corners under each corner; rows are then sorted and made
  // unique one by one (short rows, no sort over all the mesh's edges).
  std::vector<int> start(vertex_count + 1, 0);
  for (const auto& t : tets)
    for (const int v : t)
      start[static_cast<std::size_t>(v) + 1] += 3;
  for (std::size_t v = 0; v < vertex_count; ++v)
    start[v + 1] += start[v];
  std::vector<int> listed(static_cast<std::size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto& t : tets)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a != b) listed[static_cast<std::size_t>(fill[static_cast<std::size_t>(t[a])]++)] = t[b];
  VertexAdjacency adjacency;
  adjacency.offsets.assign(vertex_count + 1, 0);
  adjacency.neighbours.reserve(listed.size() / 2);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto begin = listed.begin() + start[v], end = listed.begin() + start[v + 1];
    std::sort(begin, end);
    adjacency.neighbours.insert(adjacency.neighbours.end(), begin, std::unique(begin, end));
    adjacency.offsets[v + 1] = static_cast<int>(adjacency.neighbours.size());
  }
  return adjacency;
}

double segment_triangle_intersection(const core::Vec3& p, const core::Vec3& q, const core::Vec3& a,
                                     const core::Vec3& b, const core::Vec3& c) {
  const core::Vec3 direction = q - p;
  const core::Vec3 e1 = b - a, e2 = c - a;
  const core::Vec3 h = direction.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-30) return -1.0;  // parallel to the plane
  const double inverse = 1.0 / det;
  const core::Vec3 s = p - a;
  const double u = inverse * s.dot(h);
  if (u < 0.0 || u > 1.0) return -1.0;
  const core::Vec3 qv = s.cross(e1);
  const double v = inverse * direction.dot(qv);
  if (v < 0.0 || u + v > 1.0) return -1.0;
  const double t = inverse * e2.dot(qv);
  return (t >= 0.0 && t <= 1.0) ? t : -1.0;
}

std::vector<PointPenetration> penetration_depths(std::span<const core::Vec3> x,
                                                 const VertexAdjacency& adjacency,
                                                 std::span<const int> colliding,
                                                 const PenetratedSurface& surface) {
  std::vector<char> is_colliding(x.size(), 0), processed(x.size(), 0);
  for (const int p : colliding)
    is_colliding[p] = 1;
  std::vector<double> depth(x.size(), 0.0);
  std::vector<core::Vec3> direction(x.size(), core::Vec3::Zero());
  std::vector<PointPenetration> result;

  // Stages 1 and 2: border points from the crossings of their edges to non-colliding points.
  core::BoundingBox region;
  for (const int p : colliding) {
    for (const int q : adjacency.of(p)) {
      if (!is_colliding[q]) region.add(x[q]);
    }
    region.add(x[p]);
  }
  const TriangleGrid grid(surface, region);
  std::vector<int> layer;
  for (const int p : colliding) {
    double weight_sum = 0.0, depth_sum = 0.0;
    core::Vec3 normal_sum = core::Vec3::Zero();
    for (const int q : adjacency.of(p)) {
      if (is_colliding[q]) continue;
      // The crossing nearest to p is where p's edge leaves the penetrated body.
      double best_t = 2.0;
      core::Vec3 normal = core::Vec3::Zero();
      for (const int t : grid.candidates(x[p], x[q])) {
        const auto& f = surface.faces[t];
        const core::Vec3& a = surface.positions[f[0]];
        const core::Vec3& b = surface.positions[f[1]];
        const core::Vec3& c = surface.positions[f[2]];
        const double s = segment_triangle_intersection(x[p], x[q], a, b, c);
        if (s >= 0.0 && s < best_t) {
          best_t = s;
          normal = (b - a).cross(c - a).normalized();
        }
      }
      if (best_t > 1.0) continue;
      const core::Vec3 crossing = x[p] + best_t * (x[q] - x[p]);
      const double w = weight(crossing, x[p]);
      weight_sum += w;
      depth_sum += w * (crossing - x[p]).dot(normal);  // eq. 8
      normal_sum += w * normal;                        // eq. 9
    }
    if (weight_sum == 0.0 || normal_sum.squaredNorm() == 0.0) continue;
    depth[p] = std::max(0.0, depth_sum / weight_sum);
    direction[p] = normal_sum.normalized();
    processed[p] = 1;
    layer.push_back(p);
    result.push_back({p, depth[p], direction[p], true});
  }

  // Stage 3: propagate into the colliding region, one layer of neighbours at a time.
  while (!layer.empty()) {
    std::vector<int> next;
    for (const int p : colliding) {
      if (processed[p]) continue;
      double weight_sum = 0.0, depth_sum = 0.0;
      core::Vec3 direction_sum = core::Vec3::Zero();
      for (const int q : adjacency.of(p)) {
        if (!processed[q]) continue;
        const double w = weight(x[q], x[p]);
        weight_sum += w;
        depth_sum += w * ((x[q] - x[p]).dot(direction[q]) + depth[q]);
        direction_sum += w * direction[q];
      }
      if (weight_sum == 0.0 || direction_sum.squaredNorm() == 0.0) continue;
      depth[p] = std::max(0.0, depth_sum / weight_sum);
      direction[p] = direction_sum.normalized();
      next.push_back(p);
    }
    // Mark after the sweep so each layer reads only the layers before it.
    for (const int p : next) {
      processed[p] = 1;
      result.push_back({p, depth[p], direction[p], false});
    }
    layer = std::move(next);
  }
  std::sort(result.begin(), result.end(),
            [](const auto& l, const auto& r) { return l.point < r.point; });
  return result;
}

}  // namespace viscera::sim
