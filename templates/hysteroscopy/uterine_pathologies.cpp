#include "templates/hysteroscopy/uterine_pathologies.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "core/error.h"
#include "core/primitives/ball_primitive.h"
#include "core/primitives/icosphere.h"
#include "core/primitives/pipe_primitive.h"
#include "core/scenario/landmark_frame.h"
#include "templates/vessels/vessel_tree_analysis.h"

namespace viscera::templates {
namespace {

constexpr int kTries = 200;

/// A point of the cavity wall and the unit normal into the cavity.
struct WallSite {
  core::Vec3 position, normal;
};

/// Area-weighted sampling of the cavity wall, away from the tubal orifices and the internal os.
class CavityWall {
 public:
  explicit CavityWall(const UterusShape& uterus) : surface_(uterus.surface) {
    std::vector<core::Vec3> avoid;
    for (const auto& mark : uterus.landmarks) {
      if (mark.id.starts_with("tubal-orifice") || mark.id == "cervix-internal-os")
        avoid.push_back(mark.position);
    }
    double total = 0.0;
    for (std::size_t t = 0; t < surface_.triangles.size(); ++t) {
      const auto& tri = surface_.triangles[t];
      bool usable = true;
      for (const int v : tri)
        usable = usable && uterus.cavity[static_cast<std::size_t>(v)] == 1;
      const core::Vec3 centre =
          (surface_.vertices[tri[0]] + surface_.vertices[tri[1]] + surface_.vertices[tri[2]]) / 3.0;
      for (const auto& a : avoid)
        usable = usable && (centre - a).norm() > 0.008;
      if (!usable) continue;
      total += 0.5 * (surface_.vertices[tri[1]] - surface_.vertices[tri[0]])
                         .cross(surface_.vertices[tri[2]] - surface_.vertices[tri[0]])
                         .norm();
      triangles_.push_back(static_cast<int>(t));
      cumulative_.push_back(total);
    }
    if (triangles_.empty())
      throw core::InputError("the uterus has no cavity wall to place pathologies on");
  }

  WallSite draw(core::Rng& rng) const {
    const double u = rng.uniform(0.0, cumulative_.back());
    const auto k = static_cast<std::size_t>(
        std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin());
    const auto& tri =
        surface_
            .triangles[static_cast<std::size_t>(triangles_[std::min(k, triangles_.size() - 1)])];
    double r1 = rng.uniform01(), r2 = rng.uniform01();
    if (r1 + r2 > 1.0) r1 = 1.0 - r1, r2 = 1.0 - r2;
    const auto& v = surface_.vertices;
    const core::Vec3 p = v[tri[0]] + r1 * (v[tri[1]] - v[tri[0]]) + r2 * (v[tri[2]] - v[tri[0]]);
    // The surface bounds the tissue, so its outward normal on the cavity wall points into the
    // cavity.
    return {p, (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).normalized()};
  }

 private:
  const core::SurfaceMesh& surface_;
  std::vector<int> triangles_;
  std::vector<double> cumulative_;
};

/// Moves every vertex that lies in the wall, or closer to it than `gap`, onto the wall at `gap`;
/// returns the vertices moved (the base that rests on the wall).
std::vector<int> seat_on_wall(core::SurfaceMesh& surface, const SurfaceQueries& tissue,
                              double gap) {
  std::vector<int> base;
  for (std::size_t i = 0; i < surface.vertices.size(); ++i) {
    auto& v = surface.vertices[i];
    const SurfacePoint near = tissue.closest(v);
    if (tissue.inside(v) || near.distance < gap) {
      v = near.position + gap * near.normal;
      base.push_back(static_cast<int>(i));
    }
  }
  core::compute_vertex_normals(surface);
  return base;
}

/// A unit vector perpendicular to n, pointing as much as possible along `towards`.
core::Vec3 tangent_towards(const core::Vec3& n, const core::Vec3& towards) {
  core::Vec3 t = towards - towards.dot(n) * n;
  if (t.norm() < 1e-9) t = n.unitOrthogonal();
  return t.normalized();
}

int ring_segments_for(double radius, double edge) {
  return std::clamp(static_cast<int>(std::lround(2.0 * std::numbers::pi * radius / edge)), 6, 32);
}

/// A pipe that leaves the wall at `base` along the wall normal `normal` for its first point
/// and then runs along `direction` through points at the given distances, with radii. Leaving
/// perpendicular keeps the stalk's side out of the wall, so only its flat base is seated.
core::SurfaceMesh stalked_shape(const core::Vec3& base, const core::Vec3& normal,
                                const core::Vec3& direction, const std::vector<double>& at,
                                const std::vector<double>& radii, double edge) {
  core::PipePrimitive pipe;
  for (std::size_t i = 0; i < at.size(); ++i) {
    pipe.points.push_back(i == 0 ? base
                                 : base + 0.5 * at[1] * normal + (at[i] - 0.5 * at[1]) * direction);
  }
  pipe.points[1] = base + at[1] * normal;
  pipe.radii = radii;
  pipe.start_cap = core::PipeCap::Flat;
  pipe.end_cap = core::PipeCap::Round;
  pipe.ring_segments = ring_segments_for(*std::max_element(radii.begin(), radii.end()), edge);
  pipe.axial_spacing = edge;
  return core::tessellate_pipe(pipe);
}

class Placer {
 public:
  Placer(const UterusShape& uterus, const SurfaceQueries& tissue, const PathologyRequest& request,
         core::Rng& rng)
      : tissue_(tissue), request_(request), rng_(rng), wall_(std::in_place, uterus) {
    for (const auto& mark : uterus.landmarks) {
      if (mark.id == "cervix-internal-os") internal_os_ = mark.position;
    }
  }
  /// Shapes single pathologies on any closed wall (the studio's placement by click): a ray
  /// along the wall normal that leaves the surface finds unlimited room.
  Placer(const SurfaceQueries& tissue, const PathologyRequest& request, core::Rng& rng)
      : tissue_(tissue), request_(request), rng_(rng), open_outside_(true) {}

  std::vector<PlacedPathology> run() {
    // Larger pathologies first: they need the most room.
    for (int i = 0; i < request_.intramural_myomas; ++i)
      place("myoma-intramural", [&] { return intramural(); });
    for (int i = 0; i < request_.submucosal_myomas; ++i)
      place("myoma-submucosal", [&] { return sessile(); });
    for (int i = 0; i < request_.pedunculated_myomas; ++i)
      place("myoma-pedunculated", [&] { return pedunculated(); });
    for (int i = 0; i < request_.polyps; ++i)
      place("polyp", [&] { return polyp(); });
    for (int i = 0; i < request_.adhesions; ++i)
      place("adhesion", [&] { return adhesion(); });
    return std::move(placed_);
  }

 private:
  double drawn(double mean) { return mean * rng_.uniform(0.75, 1.25); }

  /// Free distance from a wall site across the cavity to the opposite wall.
  double clearance(const WallSite& site) const {
    return tissue_.ray_hit(site.position, site.normal, 1e-5)
        .value_or(open_outside_ ? std::numeric_limits<double>::infinity() : 0.0);
  }

  template <typename Make>
  void place(const std::string& kind, Make make) {
    for (int attempt = 0; attempt < kTries; ++attempt) {
      std::optional<PlacedPathology> candidate = make();
      if (!candidate || overlaps(*candidate)) continue;
      const std::string prefix = kind.starts_with("myoma") ? "myoma" : kind;
      candidate->record.id = prefix + "-" + std::to_string(++counts_[prefix]);
      candidate->record.kind = kind;
      candidate->record.host_object = "uterus";
      candidate->record.object = candidate->record.id;
      placed_.push_back(std::move(*candidate));
      return;
    }
    throw core::InputError("cannot place a " + kind +
                           " without overlapping the others or leaving the cavity");
  }

  bool overlaps(const PlacedPathology& p) const {
    for (const auto& q : placed_) {
      const double d = segment_distance(p.axis_start, p.axis_end, q.axis_start, q.axis_end);
      if (d < p.capsule_radius + q.capsule_radius + 0.001) return true;
    }
    return false;
  }

  /// A sessile myoma: a lobulated sphere whose centre lies in the cavity, cut off radially
  /// where it would enter the wall. The shape stays star-shaped about its centre, so the cut
  /// surface cannot fold; its base lies on the wall at the gap.
  std::optional<PlacedPathology> sessile() {
    const double r = 0.5 * drawn(request_.myoma_diameter);
    const WallSite site = wall_->draw(rng_);
    if (request_.sessile_on_corpus_faces &&
        (std::abs(site.normal.y()) <= 0.6 || std::abs(site.normal.x()) >= 0.5 ||
         !room_for_the_sheath(site)))
      return std::nullopt;
    return sessile_at(site, r);
  }

  /// True when the cavity is open where a resectoscope shaving a myoma at `site` lies: a
  /// window 8 mm wide (along u = n × ẑ) and 2.5–6.5 mm above the wall, 6 mm from the site
  /// towards the cervix (v), each sampled point at least 0.5 mm from the wall, in the frame
  /// scripts place the tool in (core::landmark_frame).
  bool room_for_the_sheath(const WallSite& site) const {
    const core::LandmarkFrame frame = core::landmark_frame(site.normal);
    for (const double across : {-0.004, -0.002, 0.0, 0.002, 0.004}) {
      for (const double height : {0.0025, 0.0045, 0.0065}) {
        const core::Vec3 p = site.position + frame.offset({across, 0.006, height});
        if (tissue_.inside(p) || tissue_.closest(p).distance < 0.0005) return false;
      }
    }
    return true;
  }

 public:
  std::optional<PlacedPathology> sessile_at(const WallSite& site, double r) {
    const double protrusion = rng_.uniform(0.55, 0.85);  // fraction of the diameter in the cavity
    if (2.0 * protrusion * r + 4.0 * request_.gap > clearance(site)) return std::nullopt;
    const core::Vec3 centre = site.position + r * (2.0 * protrusion - 1.0) * site.normal;
    std::vector<core::Vec3> lobes;
    std::vector<double> heights;
    for (int k = 0; k < 5; ++k) {
      lobes.push_back(
          core::Vec3(rng_.normal(0.0, 1.0), rng_.normal(0.0, 1.0), rng_.normal(0.0, 1.0))
              .normalized());
      heights.push_back(rng_.uniform(-0.08, 0.1));
    }
    PlacedPathology p;
    p.surface =
        core::make_icosphere(1.0, core::icosphere_subdivisions_for_edge(r, request_.edge_length));
    for (std::size_t i = 0; i < p.surface.vertices.size(); ++i) {
      auto& v = p.surface.vertices[i];
      const core::Vec3 d = v.normalized();
      double radius = r;
      for (std::size_t k = 0; k < lobes.size(); ++k)
        radius += r * heights[k] * std::exp(-(d - lobes[k]).squaredNorm() / 0.5);
      if (const auto wall = tissue_.ray_hit(centre, d, 0.0)) {
        const double slant = std::max(0.3, -d.dot(site.normal));
        const double cut = *wall - request_.gap / slant;
        if (cut < radius) {
          radius = cut;
          p.base.push_back(static_cast<int>(i));
        }
      }
      if (radius < 0.2 * r) return std::nullopt;
      v = centre + radius * d;
    }
    p.surface.uvs.clear();
    core::compute_vertex_normals(p.surface);
    p.record.position = site.position;
    p.record.size = 2.0 * r;
    p.axis_start = p.axis_end = centre;
    p.capsule_radius = 1.1 * r;
    p.wall_normal = site.normal;
    return p;
  }

  std::optional<PlacedPathology> intramural() {
    const double r_drawn = 0.5 * drawn(request_.myoma_diameter);
    const WallSite site = wall_->draw(rng_);
    return intramural_at(site, r_drawn, 0.5 * 0.75 * request_.myoma_diameter);
  }

  /// A sphere of radius `r` m centred half-way through the wall beneath `site` (along the
  /// inward normal to the other side of the wall), shrunk to keep 1.5 mm of wall on both
  /// sides; nothing when that leaves it smaller than `r_min` (or 2 mm).
  std::optional<PlacedPathology> intramural_at(const WallSite& site, double r, double r_min) {
    const auto wall = tissue_.ray_hit(site.position, -site.normal, 1e-5);
    if (!wall) return std::nullopt;
    const double margin = 0.0015;
    r = std::min(r, 0.5 * *wall - margin);
    if (r < r_min || r < 0.002) return std::nullopt;
    const core::Vec3 centre = site.position - 0.5 * *wall * site.normal;
    PlacedPathology p;
    p.surface = core::make_icosphere(
        r, core::icosphere_subdivisions_for_edge(r, 1.5 * request_.edge_length), centre);
    for (const auto& v : p.surface.vertices) {
      if (!tissue_.inside(v) || tissue_.closest(v).distance < margin) return std::nullopt;
    }
    p.in_wall = true;
    for (std::size_t i = 0; i < p.surface.vertices.size(); ++i)
      p.base.push_back(static_cast<int>(i));
    p.record.position = centre;
    p.record.size = 2.0 * r;
    p.axis_start = p.axis_end = centre;
    p.capsule_radius = r;
    return p;
  }

  /// Stalk direction: leaning from the wall normal towards the internal os, as pedunculated
  /// lesions hang into the lower cavity.
  core::Vec3 stalk_direction(const WallSite& site, const core::Vec3& hang) {
    const double lean = rng_.uniform(0.35, 1.0);  // rad
    const core::Vec3 down = tangent_towards(site.normal, hang);
    return (std::cos(lean) * site.normal + std::sin(lean) * down).normalized();
  }

  /// True when the capsule along `direction` stays in the cavity with room to spare.
  bool free_path(const WallSite& site, const core::Vec3& direction, double length,
                 double radius) const {
    const auto hit = tissue_.ray_hit(site.position, direction, 1e-5);
    if (hit && *hit < length + radius + 2.0 * request_.gap) return false;
    const core::Vec3 tip = site.position + length * direction;
    return !tissue_.inside(tip) && tissue_.closest(tip).distance > radius + request_.gap;
  }

  std::optional<PlacedPathology> pedunculated() {
    const double r = 0.5 * drawn(request_.myoma_diameter);
    const WallSite site = wall_->draw(rng_);
    return pedunculated_at(site, r, internal_os_ - site.position);
  }

  std::optional<PlacedPathology> pedunculated_at(const WallSite& site, double r,
                                                 const core::Vec3& hang) {
    const core::Vec3 u = stalk_direction(site, hang);
    const double stalk = 0.8 * r, rs = std::max(0.3 * r, 0.0008);
    if (!free_path(site, u, stalk + r, r)) return std::nullopt;
    PlacedPathology p;
    p.surface =
        stalked_shape(site.position, site.normal, u,
                      {0.0, 0.5 * stalk, stalk, stalk + 0.5 * r, stalk + r, stalk + 1.5 * r},
                      {1.3 * rs, rs, 1.1 * rs, 0.85 * r, r, 0.7 * r}, request_.edge_length);
    p.base = seat_on_wall(p.surface, tissue_, request_.gap);
    p.record.position = site.position;
    p.record.size = 2.0 * r;
    p.axis_start = site.position;
    p.wall_normal = site.normal;
    p.axis_end = site.position + (stalk + r) * u;
    p.capsule_radius = 1.05 * r;
    return p;
  }

  std::optional<PlacedPathology> polyp() {
    const double length = drawn(request_.polyp_length);
    const WallSite site = wall_->draw(rng_);
    return polyp_at(site, length, internal_os_ - site.position);
  }

  std::optional<PlacedPathology> polyp_at(const WallSite& site, double length,
                                          const core::Vec3& hang) {
    const double w = 0.45 * length;
    const core::Vec3 u = stalk_direction(site, hang);
    if (!free_path(site, u, length, 0.5 * w)) return std::nullopt;
    PlacedPathology p;
    p.surface = stalked_shape(site.position, site.normal, u,
                              {0.0, 0.3 * length, 0.6 * length, 0.8 * length},
                              {0.4 * w, 0.32 * w, 0.5 * w, 0.45 * w}, request_.edge_length);
    p.base = seat_on_wall(p.surface, tissue_, request_.gap);
    p.record.position = site.position;
    p.record.size = length;
    p.axis_start = site.position;
    p.wall_normal = site.normal;
    p.axis_end = site.position + length * u;
    p.capsule_radius = 0.5 * w;
    return p;
  }

  std::optional<PlacedPathology> adhesion() {
    const double rho = drawn(request_.adhesion_radius);
    const WallSite a = wall_->draw(rng_);
    const auto span = tissue_.ray_hit(a.position, a.normal, 1e-5);
    if (!span || *span < 0.003 || *span > 0.025) return std::nullopt;
    const core::Vec3 b = a.position + *span * a.normal;
    const core::Vec3 side = a.normal.unitOrthogonal() * rng_.uniform(-0.15, 0.15) * *span;
    core::PipePrimitive pipe;
    const core::Vec3 b_normal = tissue_.closest(b).normal;
    pipe.points = {a.position, a.position + 0.25 * *span * a.normal, 0.5 * (a.position + b) + side,
                   b + 0.25 * *span * b_normal, b};
    pipe.radii = {1.8 * rho, 1.2 * rho, rho, 1.2 * rho, 1.8 * rho};
    pipe.ring_segments = ring_segments_for(1.8 * rho, request_.edge_length);
    pipe.axial_spacing = request_.edge_length;
    PlacedPathology p;
    p.surface = core::tessellate_pipe(pipe);
    p.base = seat_on_wall(p.surface, tissue_, request_.gap);
    p.record.position = a.position;
    p.record.size = *span;
    p.axis_start = a.position;
    p.axis_end = b;
    p.capsule_radius = 1.8 * rho + side.norm();
    return p;
  }

 private:
  const SurfaceQueries& tissue_;
  const PathologyRequest& request_;
  core::Rng& rng_;
  std::optional<CavityWall> wall_;
  bool open_outside_ = false;
  core::Vec3 internal_os_ = core::Vec3::Zero();
  std::map<std::string, int> counts_;
  std::vector<PlacedPathology> placed_;
};

}  // namespace

std::vector<PlacedPathology> place_pathologies(const UterusShape& uterus,
                                               const SurfaceQueries& tissue,
                                               const PathologyRequest& request, core::Rng& rng) {
  return Placer(uterus, tissue, request, rng).run();
}

std::optional<PlacedPathology> shape_pathology_at(const SurfaceQueries& tissue,
                                                  const core::Vec3& point, const std::string& kind,
                                                  double size, const core::Vec3& hang,
                                                  const PathologyRequest& request, core::Rng& rng) {
  const SurfacePoint near = tissue.closest(point);
  const WallSite site{near.position, near.normal};
  Placer placer(tissue, request, rng);
  std::optional<PlacedPathology> placed;
  if (kind == "myoma-submucosal") {
    placed = placer.sessile_at(site, 0.5 * size);
  } else if (kind == "myoma-pedunculated") {
    placed = placer.pedunculated_at(site, 0.5 * size, hang);
  } else if (kind == "polyp") {
    placed = placer.polyp_at(site, size, hang);
  } else if (kind == "myoma-intramural") {
    placed = placer.intramural_at(site, 0.5 * size, 0.5 * 0.75 * size);
  } else {
    throw core::UsageError(
        "a pathology placed on a wall is myoma-submucosal, myoma-intramural, "
        "myoma-pedunculated or polyp, not \"" +
        kind + "\"");
  }
  if (placed) placed->record.kind = kind;
  return placed;
}

}  // namespace viscera::templates
