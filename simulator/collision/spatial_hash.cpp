#include "simulator/collision/spatial_hash.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"

namespace viscera::sim {

SpatialHash::SpatialHash(double cell_size, std::size_t table_size)
    : cell_size_(cell_size), inverse_cell_size_(1.0 / cell_size), table_(table_size) {
  if (!(cell_size > 0.0)) throw core::UsageError("spatial hash cell size must be positive");
  if (table_size == 0) throw core::UsageError("spatial hash needs at least one bucket");
}

std::size_t SpatialHash::hash(std::int64_t i, std::int64_t j, std::int64_t k) const {
  // The primes of Teschner et al. 2003. Unsigned arithmetic wraps instead of overflowing.
  const auto h = (static_cast<std::uint64_t>(i) * 73856093ULL) ^ (static_cast<std::uint64_t>(j) * 19349663ULL) ^
                 (static_cast<std::uint64_t>(k) * 83492791ULL);
  return static_cast<std::size_t>(h % table_.size());
}

std::int64_t SpatialHash::cell_of(double coordinate) const {
  return static_cast<std::int64_t>(std::floor(coordinate * inverse_cell_size_));
}

std::vector<VertexInTet> SpatialHash::detect(std::span<const CollisionBodyView> bodies, bool self_collisions) {
  ++stamp_;
  // Pass 1: every vertex into the bucket of its cell.
  last_tested_.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto& positions = bodies[b].positions;
    last_tested_[b].assign(positions.size(), -1);
    for (std::size_t v = 0; v < positions.size(); ++v) {
      Bucket& bucket = table_[hash(cell_of(positions[v].x()), cell_of(positions[v].y()), cell_of(positions[v].z()))];
      if (bucket.stamp != stamp_) {
        bucket.stamp = stamp_;
        bucket.vertices.clear();
      }
      bucket.vertices.push_back({static_cast<int>(b), static_cast<int>(v)});
    }
  }

  // Without self-collisions a tet can only hold vertices of the other bodies, so a tet whose
  // box misses all their boxes is skipped before any hashing: in a resting scene that is
  // nearly every tet.
  std::vector<core::BoundingBox> body_boxes(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    for (const auto& p : bodies[b].positions) body_boxes[b].add(p);
  }
  const auto may_hold_others = [&](std::size_t tb, const core::Vec3& lo, const core::Vec3& hi) {
    if (self_collisions) return true;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (b == tb || body_boxes[b].empty()) continue;
      if ((hi.array() >= body_boxes[b].min.array()).all() && (lo.array() <= body_boxes[b].max.array()).all()) return true;
    }
    return false;
  };

  // Pass 2: every tet against the vertices hashed to the cells its box covers.
  std::vector<VertexInTet> contacts;
  std::int64_t global_tet = 0;
  for (std::size_t tb = 0; tb < bodies.size(); ++tb) {
    const auto& x = bodies[tb].positions;
    for (std::size_t t = 0; t < bodies[tb].tets.size(); ++t, ++global_tet) {
      const auto& tet = bodies[tb].tets[t];
      const core::Vec3& a = x[tet[0]];
      const core::Vec3& b = x[tet[1]];
      const core::Vec3& c = x[tet[2]];
      const core::Vec3& d = x[tet[3]];
      const core::Vec3 lo = a.cwiseMin(b).cwiseMin(c.cwiseMin(d));
      const core::Vec3 hi = a.cwiseMax(b).cwiseMax(c.cwiseMax(d));
      if (!may_hold_others(tb, lo, hi)) continue;
      for (std::int64_t k = cell_of(lo.z()); k <= cell_of(hi.z()); ++k)
        for (std::int64_t j = cell_of(lo.y()); j <= cell_of(hi.y()); ++j)
          for (std::int64_t i = cell_of(lo.x()); i <= cell_of(hi.x()); ++i) {
            const Bucket& bucket = table_[hash(i, j, k)];
            if (bucket.stamp != stamp_) continue;
            for (const auto& [vb, v] : bucket.vertices) {
              if (vb == static_cast<int>(tb) &&
                  (!self_collisions || v == tet[0] || v == tet[1] || v == tet[2] || v == tet[3])) {
                continue;
              }
              // Several cells (or hash collisions) can bring the same vertex twice.
              auto& tested = last_tested_[vb][v];
              if (tested == global_tet) continue;
              tested = global_tet;
              const core::Vec3& p = bodies[vb].positions[v];
              if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
              const auto w = core::barycentric(p, a, b, c, d);
              if (w[0] < 0.0 || w[1] < 0.0 || w[2] < 0.0 || w[3] < 0.0) continue;
              contacts.push_back({vb, v, static_cast<int>(tb), static_cast<int>(t), w});
            }
          }
    }
  }
  std::sort(contacts.begin(), contacts.end(), [](const VertexInTet& l, const VertexInTet& r) {
    return std::tie(l.vertex_body, l.vertex, l.tet_body, l.tet) < std::tie(r.vertex_body, r.vertex, r.tet_body, r.tet);
  });
  return contacts;
}

double mean_edge_length(std::span<const CollisionBodyView> bodies) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& body : bodies) {
    for (const auto& tet : body.tets) {
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
          sum += (body.positions[tet[a]] - body.positions[tet[b]]).norm();
          ++count;
        }
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace viscera::sim
