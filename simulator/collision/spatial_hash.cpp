#include "simulator/collision/spatial_hash.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::sim {

SpatialHash::SpatialHash(double cell_size, std::size_t table_size)
    : cell_size_(cell_size),
      inverse_cell_size_(1.0 / cell_size),
      table_size_(table_size),
      reduce_factor_(table_size > 0 ? ~std::uint64_t{0} / table_size + 1 : 0) {
  if (!(cell_size > 0.0)) throw core::UsageError("spatial hash cell size must be positive");
  if (table_size == 0 || table_size > 0xFFFFFFFFU)
    throw core::UsageError("spatial hash needs 1 to 2^32 - 1 buckets");
}

std::uint32_t SpatialHash::reduce(std::uint32_t x) const {
  __extension__ typedef unsigned __int128 UInt128;
  const std::uint64_t low_bits = reduce_factor_ * x;
  return static_cast<std::uint32_t>((static_cast<UInt128>(low_bits) * table_size_) >> 64);
}

std::size_t SpatialHash::hash(std::int64_t i, std::int64_t j, std::int64_t k) const {
  // The primes of Teschner et al. 2003. Unsigned arithmetic wraps instead of overflowing.
  const std::uint32_t h = (static_cast<std::uint32_t>(i) * 73856093U) ^
                          (static_cast<std::uint32_t>(j) * 19349663U) ^
                          (static_cast<std::uint32_t>(k) * 83492791U);
  return reduce(h);
}

std::int64_t SpatialHash::cell_of(double coordinate) const {
  return static_cast<std::int64_t>(std::floor(coordinate * inverse_cell_size_));
}

std::vector<VertexInTet> SpatialHash::detect(std::span<const CollisionBodyView> bodies,
                                             bool self_collisions) {
  // Without self-collisions, the vertices of a body matter only if another body has tets.
  std::size_t bodies_with_tets = 0;
  for (const auto& body : bodies)
    bodies_with_tets += body.tets.empty() ? 0 : 1;
  const auto needs_hashing = [&](std::size_t b) {
    return self_collisions || bodies_with_tets > (bodies[b].tets.empty() ? 0U : 1U);
  };

  // Cells of the vertices of bodies with tets, computed once: a tet's cell range is the range
  // of its corners' cells, the same cells its bounding box covers.
  first_cell_.assign(bodies.size() + 1, 0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    first_cell_[b + 1] = first_cell_[b] + (bodies[b].tets.empty() ? 0 : bodies[b].positions.size());
  }
  cells_.resize(first_cell_.back());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].tets.empty()) continue;
    for (std::size_t v = 0; v < bodies[b].positions.size(); ++v) {
      const auto& p = bodies[b].positions[v];
      cells_[first_cell_[b] + v] = {static_cast<std::int32_t>(cell_of(p.x())),
                                    static_cast<std::int32_t>(cell_of(p.y())),
                                    static_cast<std::int32_t>(cell_of(p.z()))};
    }
  }

  // Pass 1: every vertex into the bucket of its cell, as a counting sort by bucket.
  last_tested_.resize(bodies.size());
  bucket_start_.assign(table_size_ + 1, 0);
  vertex_bucket_.clear();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    last_tested_[b].assign(bodies[b].positions.size(), -1);
    if (!needs_hashing(b)) continue;
    for (const auto& p : bodies[b].positions) {
      const auto bucket =
          static_cast<std::uint32_t>(hash(cell_of(p.x()), cell_of(p.y()), cell_of(p.z())));
      vertex_bucket_.push_back(bucket);
      ++bucket_start_[bucket + 1];
    }
  }
  for (std::size_t h = 0; h < table_size_; ++h)
    bucket_start_[h + 1] += bucket_start_[h];
  entries_.resize(vertex_bucket_.size());
  {
    std::vector<std::uint32_t> fill(bucket_start_.begin(), bucket_start_.end() - 1);
    std::size_t next = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (!needs_hashing(b)) continue;
      for (std::size_t v = 0; v < bodies[b].positions.size(); ++v) {
        entries_[fill[vertex_bucket_[next++]]++] = {static_cast<int>(b), static_cast<int>(v)};
      }
    }
  }

  // Without self-collisions a tet can only hold vertices of the other bodies, so a tet whose
  // box misses all their boxes is skipped before any hashing: in a resting scene that is
  // nearly every tet.
  std::vector<core::BoundingBox> body_boxes(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    for (const auto& p : bodies[b].positions)
      body_boxes[b].add(p);
  }
  const auto may_hold_others = [&](std::size_t tb, const core::Vec3& lo, const core::Vec3& hi) {
    if (self_collisions) return true;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (b == tb || body_boxes[b].empty()) continue;
      if ((hi.array() >= body_boxes[b].min.array()).all() &&
          (lo.array() <= body_boxes[b].max.array()).all())
        return true;
    }
    return false;
  };

  // Pass 2: every tet against the vertices hashed to the cells its box covers.
  std::vector<VertexInTet> contacts;
  struct Candidate {
    core::Vec3 position;  // copied, so the hot loop reads one contiguous array
    int body, vertex;
  };
  std::vector<Candidate> candidates;
  std::array<std::int32_t, 3> candidates_lo{1, 1, 1}, candidates_hi{0, 0, 0};  // an empty range
  std::int64_t range_stamp = 0;
  for (std::size_t tb = 0; tb < bodies.size(); ++tb) {
    const auto& x = bodies[tb].positions;
    candidates_lo = {1, 1, 1};  // a new body: its tets start a fresh range
    candidates_hi = {0, 0, 0};
    for (std::size_t t = 0; t < bodies[tb].tets.size(); ++t) {
      const auto& tet = bodies[tb].tets[t];
      const core::Vec3& a = x[tet[0]];
      const core::Vec3& b = x[tet[1]];
      const core::Vec3& c = x[tet[2]];
      const core::Vec3& d = x[tet[3]];
      const core::Vec3 lo = a.cwiseMin(b).cwiseMin(c.cwiseMin(d));
      const core::Vec3 hi = a.cwiseMax(b).cwiseMax(c.cwiseMax(d));
      if (!may_hold_others(tb, lo, hi)) continue;
      // Barycentric coordinates as ratios of sub-volumes: the three cross products and the
      // volume belong to the tet, so each candidate vertex then costs three dot products.
      const core::Vec3 ab = b - a, ac = c - a, ad = d - a;
      const core::Vec3 n_b = ac.cross(ad), n_c = ad.cross(ab), n_d = ab.cross(ac);
      const double volume6 = ab.dot(n_b);
      if (volume6 == 0.0) continue;  // a flat tet holds nothing
      const double inverse_volume6 = 1.0 / volume6;
      const auto* cell = &cells_[first_cell_[tb]];
      std::array<std::int32_t, 3> c_lo = cell[tet[0]], c_hi = cell[tet[0]];
      for (int corner = 1; corner < 4; ++corner) {
        for (int axis = 0; axis < 3; ++axis) {
          c_lo[axis] = std::min(c_lo[axis], cell[tet[corner]][axis]);
          c_hi[axis] = std::max(c_hi[axis], cell[tet[corner]][axis]);
        }
      }
      // Tets of one mesh cell usually cover the same grid cells as the tet before them (the
      // six tets of a cube share its box), so the candidate vertices of a cell range are
      // gathered once — without duplicates from hash collisions — and reused.
      if (c_lo != candidates_lo || c_hi != candidates_hi) {
        candidates_lo = c_lo;
        candidates_hi = c_hi;
        ++range_stamp;
        candidates.clear();
        for (std::int64_t k = c_lo[2]; k <= c_hi[2]; ++k)
          for (std::int64_t j = c_lo[1]; j <= c_hi[1]; ++j)
            for (std::int64_t i = c_lo[0]; i <= c_hi[0]; ++i) {
              const std::size_t h = hash(i, j, k);
              for (std::uint32_t e = bucket_start_[h]; e < bucket_start_[h + 1]; ++e) {
                const auto [vb, v] = entries_[e];
                // Without self-collisions a tet never holds its own body's vertices: they
                // are left out here, where a tet next to its body's dense vertices would
                // otherwise test each of them.
                if (!self_collisions && vb == static_cast<int>(tb)) continue;
                auto& seen = last_tested_[vb][v];
                if (seen == range_stamp) continue;
                seen = range_stamp;
                candidates.push_back({bodies[vb].positions[v], vb, v});
              }
            }
      }
      for (const auto& [p, vb, v] : candidates) {
        if (p.x() < lo.x() || p.x() > hi.x() || p.y() < lo.y() || p.y() > hi.y() ||
            p.z() < lo.z() || p.z() > hi.z()) {
          continue;
        }
        if (vb == static_cast<int>(tb) &&
            (!self_collisions || v == tet[0] || v == tet[1] || v == tet[2] || v == tet[3])) {
          continue;
        }
        const core::Vec3 ap = p - a;
        const double wb = ap.dot(n_b) * inverse_volume6;
        if (wb < 0.0) continue;
        const double wc = ap.dot(n_c) * inverse_volume6;
        if (wc < 0.0) continue;
        const double wd = ap.dot(n_d) * inverse_volume6;
        const double wa = 1.0 - wb - wc - wd;
        if (wd < 0.0 || wa < 0.0) continue;
        contacts.push_back({vb, v, static_cast<int>(tb), static_cast<int>(t), {wa, wb, wc, wd}});
      }
    }
  }
  std::sort(contacts.begin(), contacts.end(), [](const VertexInTet& l, const VertexInTet& r) {
    return std::tie(l.vertex_body, l.vertex, l.tet_body, l.tet) <
           std::tie(r.vertex_body, r.vertex, r.tet_body, r.tet);
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
