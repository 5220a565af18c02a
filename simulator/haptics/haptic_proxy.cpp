#include "simulator/haptics/haptic_proxy.h"

#include <algorithm>
#include <limits>

#include "simulator/collision/penetration_depth.h"

namespace viscera::sim {

ProxySurface::ProxySurface(std::vector<core::Triangle> faces) : faces_(std::move(faces)) {
  neighbours_.assign(faces_.size(), {-1, -1, -1});
  // Each directed edge (a, b) of one triangle meets (b, a) of its neighbour on a closed,
  // consistently oriented surface: look for it among the triangles around b. Where several
  // triangles share a directed edge (a non-manifold input), the last of them is the neighbour.
  int vertices = 0;
  for (const auto& f : faces_)
    for (const int v : f)
      vertices = std::max(vertices, v + 1);
  std::vector<int> start(static_cast<std::size_t>(vertices) + 1, 0);
  for (const auto& f : faces_)
    for (const int v : f)
      ++start[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < static_cast<std::size_t>(vertices); ++v)
    start[v + 1] += start[v];
  std::vector<int> around(static_cast<std::size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < faces_.size(); ++t)
    for (const int v : faces_[t])
      around[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<int>(t);
  for (std::size_t t = 0; t < faces_.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      const int a = faces_[t][e], b = faces_[t][(e + 1) % 3];
      for (int k = start[static_cast<std::size_t>(b)]; k < start[static_cast<std::size_t>(b) + 1];
           ++k) {
        const auto& g = faces_[static_cast<std::size_t>(around[static_cast<std::size_t>(k)])];
        for (int d = 0; d < 3; ++d)
          if (g[d] == b && g[(d + 1) % 3] == a)
            neighbours_[t][e] = around[static_cast<std::size_t>(k)];
      }
    }
  }
}

ProxySurface ProxySurface::joined(std::span<const ProxySurface> parts,
                                  std::span<const int> vertex_offsets) {
  ProxySurface out;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const int face_offset = static_cast<int>(out.faces_.size());
    for (std::size_t t = 0; t < parts[k].faces_.size(); ++t) {
      core::Triangle f = parts[k].faces_[t];
      std::array<int, 3> across = parts[k].neighbours_[t];
      for (int e = 0; e < 3; ++e) {
        f[e] += vertex_offsets[k];
        if (across[e] >= 0) across[e] += face_offset;
      }
      out.faces_.push_back(f);
      out.neighbours_.push_back(across);
    }
  }
  return out;
}

core::Vec3 closest_point_on_triangle(const core::Vec3& p, const core::Vec3& a, const core::Vec3& b,
                                     const core::Vec3& c, std::array<double, 3>& w) {
  const core::Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return w = {1, 0, 0}, a;
  const core::Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return w = {0, 1, 0}, b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return w = {1 - v, v, 0}, a + v * ab;
  }
  const core::Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return w = {0, 0, 1}, c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double v = d2 / (d2 - d6);
    return w = {1 - v, 0, v}, a + v * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return w = {0, 1 - v, v}, b + v * (c - b);
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, u = vc * denominator;
  w = {1 - v - u, v, u};
  return a + v * ab + u * ac;
}

std::array<std::pair<int, core::Vec3>, 3> distribute_to_triangle(const core::Triangle& triangle,
                                                                 const std::array<double, 3>& w,
                                                                 const core::Vec3& force) {
  return {{{triangle[0], w[0] * force}, {triangle[1], w[1] * force}, {triangle[2], w[2] * force}}};
}

HapticProxy::HapticProxy(double stiffness) : stiffness_(stiffness) {}

void HapticProxy::reset(const core::Vec3& position) {
  proxy_ = tip_ = position;
  contact_ = {};
}

core::Vec3 HapticProxy::force() const {
  return in_contact() ? core::Vec3(stiffness_ * (proxy_ - tip_)) : core::Vec3::Zero();
}

void HapticProxy::update(const core::Vec3& tip, const ProxySurface& surface,
                         std::span<const core::Vec3> x, ProxySurfaceTree* tree) {
  tip_ = tip;
  const auto& faces = surface.faces();
  const auto corner = [&](int t, int k) -> const core::Vec3& {
    return x[faces[static_cast<std::size_t>(t)][k]];
  };

  if (in_contact()) {
    // The surface moved since the last update: the proxy rides on its triangle.
    const int t = contact_.triangle;
    proxy_ = contact_.barycentric[0] * corner(t, 0) + contact_.barycentric[1] * corner(t, 1) +
             contact_.barycentric[2] * corner(t, 2);
    const core::Vec3 normal = (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0));
    if ((tip - proxy_).dot(normal) >= 0.0) {
      contact_ = {};  // the tip is back outside this face: free again, but re-check the path
    } else {
      // Walk towards the point of the surface nearest to the tip.
      int current = t;
      std::array<double, 3> w{};
      core::Vec3 best = closest_point_on_triangle(tip, corner(current, 0), corner(current, 1),
                                                  corner(current, 2), w);
      for (int step = 0; step < 256; ++step) {
        int across = -1;
        for (int e = 0; e < 3; ++e) {
          if (w[(e + 2) % 3] == 0.0 && surface.neighbour(current, e) >= 0)
            across = surface.neighbour(current, e);
        }
        if (across < 0) break;
        std::array<double, 3> w_next{};
        const core::Vec3 next = closest_point_on_triangle(tip, corner(across, 0), corner(across, 1),
                                                          corner(across, 2), w_next);
        if ((next - tip).squaredNorm() >= (best - tip).squaredNorm()) break;
        current = across;
        best = next;
        w = w_next;
      }
      proxy_ = best;
      contact_ = {current, w};
      return;
    }
  }

  // Free: does the path from the proxy to the tip enter the surface from outside? (A path of
  // no length enters nothing: the proxy already is at the tip.)
  if (proxy_ == tip) return;
  double first = std::numeric_limits<double>::infinity();
  int hit = -1;
  if (tree != nullptr) {
    const ProxySurfaceTree::Entry entry = tree->first_entry(proxy_, tip, faces, x);
    hit = entry.face;
    first = entry.s;
  }
  for (std::size_t t = 0; tree == nullptr && t < faces.size(); ++t) {
    const core::Vec3& a = x[faces[t][0]];
    const core::Vec3& b = x[faces[t][1]];
    const core::Vec3& c = x[faces[t][2]];
    if ((tip - proxy_).dot((b - a).cross(c - a)) >= 0.0) continue;  // leaving or grazing
    const double s = segment_triangle_intersection(proxy_, tip, a, b, c);
    if (s >= 0.0 && s < first) {
      first = s;
      hit = static_cast<int>(t);
    }
  }
  if (hit < 0) {
    proxy_ = tip;
    return;
  }
  std::array<double, 3> w{};
  proxy_ = closest_point_on_triangle(proxy_ + first * (tip - proxy_), corner(hit, 0),
                                     corner(hit, 1), corner(hit, 2), w);
  contact_ = {hit, w};
  update(tip, surface, x, tree);  // settle on the surface point nearest the tip
}

bool HapticProxy::recapture(const ProxySurface& surface, std::span<const core::Vec3> x,
                            ProxySurfaceTree* tree) {
  if (in_contact()) return false;
  const auto& faces = surface.faces();
  // A direction no mesh built on axes or regular polyhedra lines up with, so the ray meets
  // edges and vertices only by accident; far enough to leave any body of a scene in metres.
  const core::Vec3 far =
      tip_ + 1.0e3 * core::Vec3(0.5773502691896257, 0.5773662691896258, 0.5773342691896259);
  int crossings = 0;
  if (tree != nullptr) {
    crossings = tree->crossings(tip_, far, faces, x);
  } else {
    for (const auto& f : faces) {
      if (segment_triangle_intersection(tip_, far, x[f[0]], x[f[1]], x[f[2]]) >= 0.0) ++crossings;
    }
  }
  if (crossings % 2 == 0) return false;
  int nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  std::array<double, 3> w{}, best_w{};
  core::Vec3 point = tip_;
  for (std::size_t t = 0; t < faces.size(); ++t) {
    const core::Vec3 p =
        closest_point_on_triangle(tip_, x[faces[t][0]], x[faces[t][1]], x[faces[t][2]], w);
    if ((p - tip_).squaredNorm() < best) {
      best = (p - tip_).squaredNorm();
      nearest = static_cast<int>(t);
      best_w = w;
      point = p;
    }
  }
  if (nearest < 0) return false;
  proxy_ = point;
  contact_ = {nearest, best_w};
  return true;
}

}  // namespace viscera::sim
