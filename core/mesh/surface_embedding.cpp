#include "core/mesh/surface_embedding.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace viscera::core {

std::array<double, 4> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                  const Vec3& d) {
  // Ratios of signed sub-volumes: cheaper than a 3×3 solve and exact for points outside too.
  const Vec3 ab = b - a, ac = c - a, ad = d - a, ap = p - a;
  const double volume6 = ab.dot(ac.cross(ad));
  if (volume6 == 0.0) return {1.0, 0.0, 0.0, 0.0};
  const double wb = ap.dot(ac.cross(ad)) / volume6;
  const double wc = ab.dot(ap.cross(ad)) / volume6;
  const double wd = ab.dot(ac.cross(ap)) / volume6;
  return {1.0 - wb - wc - wd, wb, wc, wd};
}

namespace {

/// Uniform grid of tet bounding boxes: each cell lists the tets that overlap it.
class TetGrid {
 public:
  explicit TetGrid(const TetMesh& body) {
    BoundingBox box;
    double extent_sum = 0.0;
    for (const auto& tet : body.tets) {
      BoundingBox tb;
      for (const int n : tet)
        tb.add(body.nodes[n]);
      extent_sum += tb.size().maxCoeff();
      box.add(tb.min);
      box.add(tb.max);
    }
    cell_ = std::max(extent_sum / static_cast<double>(body.tets.size()), 1e-12);
    origin_ = box.min;
    for (int i = 0; i < 3; ++i) {
      dims_[i] = std::max(1, static_cast<int>(std::ceil(box.size()[i] / cell_)) + 1);
    }
    cells_.resize(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2]);
    for (std::size_t t = 0; t < body.tets.size(); ++t) {
      BoundingBox tb;
      for (const int n : body.tets[t])
        tb.add(body.nodes[n]);
      const auto lo = cell_of(tb.min), hi = cell_of(tb.max);
      for (int k = lo[2]; k <= hi[2]; ++k)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int i = lo[0]; i <= hi[0]; ++i)
            cells_[index(i, j, k)].push_back(static_cast<int>(t));
    }
  }

  std::array<int, 3> cell_of(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int i = 0; i < 3; ++i) {
      c[i] = std::clamp(static_cast<int>(std::floor((p[i] - origin_[i]) / cell_)), 0, dims_[i] - 1);
    }
    return c;
  }
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
  }
  /// Tets in the cells within `ring` cells of p's cell.
  template <typename Visit>
  void visit_near(const Vec3& p, int ring, Visit&& visit) const {
    const auto c = cell_of(p);
    for (int k = std::max(0, c[2] - ring); k <= std::min(dims_[2] - 1, c[2] + ring); ++k)
      for (int j = std::max(0, c[1] - ring); j <= std::min(dims_[1] - 1, c[1] + ring); ++j)
        for (int i = std::max(0, c[0] - ring); i <= std::min(dims_[0] - 1, c[0] + ring); ++i)
          for (const int t : cells_[index(i, j, k)])
            visit(t);
  }
  int max_ring() const { return std::max({dims_[0], dims_[1], dims_[2]}); }

 private:
  double cell_ = 1.0;
  Vec3 origin_ = Vec3::Zero();
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::vector<int>> cells_;
};

}  // namespace

SurfaceEmbedding embed_points(const std::vector<Vec3>& points, const TetMesh& body) {
  if (body.tets.empty()) throw InputError("cannot embed a surface in a body without tetrahedra");
  const TetGrid grid(body);
  SurfaceEmbedding embedding;
  embedding.tet.resize(points.size());
  embedding.weights.resize(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) {
    int best = -1;
    double best_min_weight = -std::numeric_limits<double>::infinity();
    std::array<double, 4> best_weights{};
    // The point's own cell lists every tet whose box covers it, so ring 0 finds the containing
    // tet; points outside the body widen the search to find the nearest tet.
    for (int ring = 0; best < 0 || (best_min_weight < -1e-9 && ring <= 2); ++ring) {
      grid.visit_near(points[v], ring, [&](int t) {
        const auto& tet = body.tets[t];
        const auto w = barycentric(points[v], body.nodes[tet[0]], body.nodes[tet[1]],
                                   body.nodes[tet[2]], body.nodes[tet[3]]);
        const double min_weight = *std::min_element(w.begin(), w.end());
        if (min_weight > best_min_weight || (min_weight == best_min_weight && t < best)) {
          best_min_weight = min_weight;
          best = t;
          best_weights = w;
        }
      });
      if (ring > grid.max_ring()) break;
    }
    embedding.tet[v] = best;
    embedding.weights[v] = best_weights;
  }
  return embedding;
}

std::vector<Vec3> embedded_positions(const SurfaceEmbedding& embedding,
                                     const std::vector<Tetrahedron>& tets,
                                     std::span<const Vec3> body_nodes) {
  std::vector<Vec3> out(embedding.tet.size());
  for (std::size_t v = 0; v < out.size(); ++v) {
    const auto& tet = tets[embedding.tet[v]];
    const auto& w = embedding.weights[v];
    out[v] = w[0] * body_nodes[tet[0]] + w[1] * body_nodes[tet[1]] + w[2] * body_nodes[tet[2]] +
             w[3] * body_nodes[tet[3]];
  }
  return out;
}

}  // namespace viscera::core
