#include "templates/vessels/vessel_pipe_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "core/error.h"
#include "templates/vessels/vessel_tree_analysis.h"

namespace viscera::templates {
namespace {

using core::Vec3;

/// Signed distance to a capsule around segment a-b of radius r (negative inside).
double capsule_distance(const Vec3& p, const Vec3& a, const Vec3& b, double r) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm() - r;
}

/// Polynomial smooth minimum of width k: equals min(a, b) when |a − b| ≥ k.
double smooth_min(double a, double b, double k) {
  if (k <= 0.0) return std::min(a, b);
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

/// A bifurcation: a parent and its children, blended together near their common node.
struct Junction {
  int parent = -1;
  std::vector<int> children;
  double blend = 0.0;  ///< m
};

class PipeField {
 public:
  PipeField(const core::VesselTree& tree, const std::vector<bool>& meshed, double blend_fraction,
            double cell)
      : tree_(tree), cell_(cell) {
    const auto children = segment_children(tree);
    for (std::size_t i = 0; i < tree.segments.size(); ++i) {
      if (!meshed[i]) continue;
      std::vector<int> kept;
      for (const int c : children[i]) {
        if (meshed[c]) kept.push_back(c);
      }
      if (kept.size() < 2) continue;  // chain joints stay sharp: min() of two tubes is exact there
      Junction j;
      j.parent = static_cast<int>(i);
      j.children = kept;
      double thinnest = tree.segments[i].radius;
      for (const int c : kept)
        thinnest = std::min(thinnest, tree.segments[c].radius);
      j.blend = blend_fraction * thinnest;
      junctions_.push_back(j);
    }
    for (std::size_t i = 0; i < tree.segments.size(); ++i) {
      if (meshed[i]) insert(static_cast<int>(i), segment_box(static_cast<int>(i), 0.0), segments_);
    }
    for (std::size_t j = 0; j < junctions_.size(); ++j) {
      const Vec3& node = tree.segments[junctions_[j].parent].distal;
      const double reach = 2.0 * tree.segments[junctions_[j].parent].radius + junctions_[j].blend;
      insert(static_cast<int>(j), {node - Vec3::Constant(reach), node + Vec3::Constant(reach)},
             junction_cells_);
    }
  }

  double value(const Vec3& p) const {
    double f = 1e300;
    const auto key = cell_key(p);
    if (const auto it = segments_.find(key); it != segments_.end()) {
      for (const int i : it->second)
        f = std::min(f, distance(i, p));
    }
    if (const auto it = junction_cells_.find(key); it != junction_cells_.end()) {
      for (const int j : it->second) {
        const Junction& junction = junctions_[j];
        double blended = distance(junction.parent, p);
        for (const int c : junction.children)
          blended = smooth_min(blended, distance(c, p), junction.blend);
        f = std::min(f, blended);
      }
    }
    return f;
  }

  core::BoundingBox segment_box(int i, double pad) const {
    const auto& s = tree_.segments[i];
    const Vec3 r = Vec3::Constant(s.radius + pad);
    return {s.proximal.cwiseMin(s.distal) - r, s.proximal.cwiseMax(s.distal) + r};
  }

 private:
  using Cells = std::unordered_map<std::uint64_t, std::vector<int>>;

  double distance(int i, const Vec3& p) const {
    const auto& s = tree_.segments[i];
    return capsule_distance(p, s.proximal, s.distal, s.radius);
  }
  std::uint64_t cell_key(const Vec3& p) const {
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a) {
      key = key * 2097152ULL + static_cast<std::uint64_t>(
                                   static_cast<std::int64_t>(std::floor(p[a] / cell_)) + 1048576);
    }
    return key;
  }
  void insert(int id, const core::BoundingBox& box, Cells& cells) const {
    // Every lookup cell the box touches, padded by one cell so a corner on a cell face sees it.
    const Vec3 lo = box.min - Vec3::Constant(cell_), hi = box.max + Vec3::Constant(cell_);
    for (double x = std::floor(lo.x() / cell_); x <= std::floor(hi.x() / cell_); ++x)
      for (double y = std::floor(lo.y() / cell_); y <= std::floor(hi.y() / cell_); ++y)
        for (double z = std::floor(lo.z() / cell_); z <= std::floor(hi.z() / cell_); ++z) {
          cells[cell_key(Vec3((x + 0.5) * cell_, (y + 0.5) * cell_, (z + 0.5) * cell_))].push_back(
              id);
        }
  }

  const core::VesselTree& tree_;
  double cell_;
  std::vector<Junction> junctions_;
  Cells segments_, junction_cells_;
};

/// Freudenthal split of a cube into six tetrahedra sharing the diagonal from corner 0 to 7;
/// corners are numbered by bits x=1, y=2, z=4. Neighbouring cubes split shared faces alike.
constexpr std::array<std::array<int, 4>, 6> kTets = {
    {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

}  // namespace

core::SurfaceMesh vessel_pipe_mesh(const core::VesselTree& tree, const PipeMeshOptions& options,
                                   core::Progress& progress) {
  if (tree.segments.empty()) throw core::UsageError("the vessel tree has no segments to mesh");
  core::BoundingBox extent;
  double thinnest = INFINITY;
  for (const auto& s : tree.segments) {
    extent.add(s.proximal);
    extent.add(s.distal);
    thinnest = std::min(thinnest, s.radius);
  }
  double h = options.voxel_size;
  if (h <= 0.0) h = std::max(thinnest / 1.5, extent.size().norm() / 400.0);
  const double min_radius = options.min_radius > 0.0 ? options.min_radius : 0.75 * h;
  std::vector<bool> meshed(tree.segments.size());
  double max_radius = 0.0;
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    meshed[i] = tree.segments[i].radius >= min_radius;
    if (meshed[i]) max_radius = std::max(max_radius, tree.segments[i].radius);
  }
  if (max_radius == 0.0) throw core::UsageError("no segment is thicker than the minimum radius");

  const PipeField field(tree, meshed, options.blend, std::max(4.0 * h, 2.0 * max_radius));

  // Active cells: grid cubes within reach of a meshed segment's wall. Cubes farther away have
  // all corners outside, so no surface crosses between them and an active cube.
  // Grid coordinates packed 19 bits per axis (±262144 cells), leaving 5 bits for edge keys.
  constexpr std::int64_t kOffset = 262144;
  const auto pack = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return (static_cast<std::uint64_t>(x + kOffset) << 38) |
           (static_cast<std::uint64_t>(y + kOffset) << 19) |
           static_cast<std::uint64_t>(z + kOffset);
  };
  std::vector<std::uint64_t> cells;
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    if (!meshed[i]) continue;
    const auto& s = tree.segments[i];
    const double reach = s.radius * (1.0 + options.blend) + 2.0 * h;
    const auto box = field.segment_box(static_cast<int>(i), reach - s.radius);
    const auto lo = (box.min / h).array().floor().cast<std::int64_t>();
    const auto hi = (box.max / h).array().floor().cast<std::int64_t>();
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const Vec3 centre((x + 0.5) * h, (y + 0.5) * h, (z + 0.5) * h);
          if (capsule_distance(centre, s.proximal, s.distal, s.radius) < reach - s.radius) {
            cells.push_back(pack(x, y, z));
          }
        }
    if (cells.size() > 2 * options.max_cells) {
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      if (cells.size() > options.max_cells) {
        throw core::UsageError("the pipe mesh needs more than " +
                               std::to_string(options.max_cells) +
                               " grid cells; raise the voxel size or the minimum radius");
      }
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  if (cells.size() > options.max_cells) {
    throw core::UsageError("the pipe mesh needs more than " + std::to_string(options.max_cells) +
                           " grid cells; raise the voxel size or the minimum radius");
  }
  progress.begin_stage("meshing vessels", static_cast<std::int64_t>(cells.size()));

  std::unordered_map<std::uint64_t, double> corner_values;
  corner_values.reserve(cells.size() * 2);
  const auto corner_value = [&](std::uint64_t key, const Vec3& p) {
    const auto [it, inserted] = corner_values.try_emplace(key, 0.0);
    if (inserted) {
      const double f = field.value(p);
      it->second = f == 0.0 ? 1e-12 * h : f;  // no corner exactly on the surface
    }
    return it->second;
  };
  core::SurfaceMesh mesh;
  std::unordered_map<std::uint64_t, int> edge_vertex;  ///< (lower corner key, direction) → vertex
  edge_vertex.reserve(cells.size() * 3);

  std::int64_t done = 0;
  for (const std::uint64_t cell : cells) {
    const std::int64_t cx = static_cast<std::int64_t>(cell >> 38) - kOffset;
    const std::int64_t cy = static_cast<std::int64_t>((cell >> 19) & 0x7FFFF) - kOffset;
    const std::int64_t cz = static_cast<std::int64_t>(cell & 0x7FFFF) - kOffset;
    std::array<std::uint64_t, 8> key{};
    std::array<Vec3, 8> position;
    std::array<double, 8> value{};
    for (int c = 0; c < 8; ++c) {
      const std::int64_t x = cx + (c & 1), y = cy + ((c >> 1) & 1), z = cz + ((c >> 2) & 1);
      key[c] = pack(x, y, z);
      position[c] = Vec3(x * h, y * h, z * h);
      value[c] = corner_value(key[c], position[c]);
    }
    for (const auto& tet : kTets) {
      int inside[4], outside[4], n_in = 0, n_out = 0;
      for (const int c : tet)
        (value[c] < 0.0 ? inside[n_in++] : outside[n_out++]) = c;
      if (n_in == 0 || n_out == 0) continue;
      const auto edge = [&](int a, int b) {
        int first = a, second = b;
        if (key[first] > key[second]) std::swap(first, second);
        // Corner bits give each corner's offset in the cube; the edge's direction code is 0..26.
        const int direction = ((second & 1) - (first & 1) + 1) * 9 +
                              (((second >> 1) & 1) - ((first >> 1) & 1) + 1) * 3 +
                              (((second >> 2) & 1) - ((first >> 2) & 1) + 1);
        const auto [it, inserted] =
            edge_vertex.try_emplace((key[first] << 5) | static_cast<std::uint64_t>(direction),
                                    static_cast<int>(mesh.vertices.size()));
        if (inserted) {
          // Interpolated from the lower key's end, so both cubes sharing the edge agree.
          const double t = value[first] / (value[first] - value[second]);
          mesh.vertices.push_back(position[first] + t * (position[second] - position[first]));
        }
        return it->second;
      };
      // Orientation from the corners' exact integer offsets, never from the interpolated points:
      // a triangle squeezed to zero area still gets the orientation its neighbours expect.
      const auto offset = [](int c) { return Eigen::Vector3i(c & 1, (c >> 1) & 1, (c >> 2) & 1); };
      const auto orientation = [&](int p, int q, int r, int t) {
        const Eigen::Vector3i u = offset(q) - offset(p), v = offset(r) - offset(p),
                              w = offset(t) - offset(p);
        return u.dot(v.cross(w));
      };
      const auto emit = [&](int a, int b, int c, bool flip) {
        mesh.triangles.push_back(flip ? core::Triangle{a, c, b} : core::Triangle{a, b, c});
      };
      if (n_in == 1 || n_out == 1) {
        // (e0, e1, e2) on edges from the lone corner l faces away from l when det(o−l) > 0;
        // outward means away from a lone inside corner and towards a lone outside one.
        const int lone = n_in == 1 ? inside[0] : outside[0];
        const int* others = n_in == 1 ? outside : inside;
        const bool away = orientation(lone, others[0], others[1], others[2]) > 0;
        emit(edge(lone, others[0]), edge(lone, others[1]), edge(lone, others[2]),
             away != (n_in == 1));
      } else {
        // Inside a, b and outside c, d: the cycle ac, ad, bd, bc faces c, d when det > 0.
        const int a = inside[0], b = inside[1], c = outside[0], d = outside[1];
        const bool flip = orientation(a, b, c, d) < 0;
        const int ac = edge(a, c), ad = edge(a, d), bd = edge(b, d), bc = edge(b, c);
        emit(ac, ad, bd, flip);
        emit(ac, bd, bc, flip);
      }
    }
    if (++done % 4096 == 0) progress.step(4096);
  }
  // Triangles with two vertices at one point (a corner value just past zero) carry no area.
  std::erase_if(mesh.triangles, [&](const core::Triangle& t) {
    return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
  });
  core::compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace viscera::templates
