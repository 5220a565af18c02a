#include "templates/hysteroscopy/uterus_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "templates/geometry/ring_surface.h"

namespace viscera::templates {
namespace {

constexpr double kMinWall = 0.004;  // m of tissue everywhere between cavity or canal and outside

/// One point of the meridian: the ring at height z with semi-axes a (x) and b (y).
struct MeridianPoint {
  double z, a, b;
  double edge;          ///< target edge length of the ring, m
  std::uint8_t region;  ///< 1 cavity, 2 canal, 0 outside
};

/// Heights of the landmarks of the profile.
struct Profile {
  double z_io, z_cap, z_top_in, z_widest, cap, dome, half_width_in, half_depth_in;
};

Profile profile_of(const UterusDimensions& d) {
  Profile p{};
  p.z_io = d.cervix_length;
  p.z_top_in = d.cervix_length + d.cavity_length;
  p.cap = 0.2 * d.cavity_length;
  p.z_cap = p.z_top_in - p.cap;
  p.z_widest = p.z_cap - 0.002;
  p.dome = d.length - p.z_widest;
  p.half_width_in = 0.5 * d.cavity_width;
  p.half_depth_in = 0.5 * d.cavity_depth;
  return p;
}

double smoothstep(double s) {
  return s * s * (3.0 - 2.0 * s);
}

/// Outer semi-axes at height z (0 ≤ z ≤ length).
std::pair<double, double> outer_axes(const UterusDimensions& d, const Profile& p, double z) {
  if (z <= p.z_io) return {d.cervix_radius, d.cervix_radius};
  if (z <= p.z_widest) {
    const double s = smoothstep((z - p.z_io) / (p.z_widest - p.z_io));
    return {d.cervix_radius + (0.5 * d.width - d.cervix_radius) * s,
            d.cervix_radius + (0.5 * d.thickness - d.cervix_radius) * s};
  }
  const double u = std::min(1.0, (z - p.z_widest) / p.dome);
  const double c = std::sqrt(std::max(0.0, 1.0 - u * u));
  return {0.5 * d.width * c, 0.5 * d.thickness * c};
}

/// Cavity or canal semi-axes at height z (0 ≤ z ≤ top of the cavity).
std::pair<double, double> inner_axes(const UterusDimensions& d, const Profile& p, double z) {
  if (z <= p.z_io) {
    const double r =
        d.canal_radius * (1.0 + 0.2 * std::sin(std::numbers::pi * z / d.cervix_length));
    return {r, r};
  }
  if (z <= p.z_cap) {
    const double s = std::pow((z - p.z_io) / (p.z_cap - p.z_io), 1.3);
    return {d.canal_radius + (p.half_width_in - d.canal_radius) * s,
            d.canal_radius + (p.half_depth_in - d.canal_radius) * s};
  }
  const double u = std::min(1.0, (z - p.z_cap) / p.cap);
  const double c = std::sqrt(std::max(0.0, 1.0 - u * u));
  return {p.half_width_in * c, p.half_depth_in * c};
}

/// The meridian densely sampled from the top of the cavity down and up the outside.
std::vector<MeridianPoint> meridian(const UterusDimensions& d, const Profile& p) {
  constexpr int kSamples = 400;
  const double e_out = d.edge_length, e_cav = 0.7 * d.edge_length, e_canal = 0.5 * d.edge_length;
  std::vector<MeridianPoint> m;
  for (int i = 1; i <= kSamples; ++i) {  // cavity dome, from the pole (excluded)
    const double alpha = 0.5 * std::numbers::pi * i / kSamples;
    m.push_back({p.z_cap + p.cap * std::cos(alpha), p.half_width_in * std::sin(alpha),
                 p.half_depth_in * std::sin(alpha), e_cav, 1});
  }
  for (int i = 1; i <= kSamples; ++i) {  // cavity body down to the internal os
    const double z = p.z_cap - (p.z_cap - p.z_io) * i / kSamples;
    const auto [a, b] = inner_axes(d, p, z);
    m.push_back({z, a, b, e_cav, 1});
  }
  for (int i = 1; i <= kSamples; ++i) {  // cervical canal down to the external os
    const double z = p.z_io * (1.0 - static_cast<double>(i) / kSamples);
    const auto [a, b] = inner_axes(d, p, z);
    m.push_back({z, a, b, e_canal, 2});
  }
  const double lip = 0.15 * (d.cervix_radius - d.canal_radius);
  for (int i = 1; i < kSamples; ++i) {  // round the lip of the external os
    const double v = static_cast<double>(i) / kSamples;
    const double r = d.canal_radius + (d.cervix_radius - d.canal_radius) * v;
    m.push_back({-lip * std::sin(std::numbers::pi * v), r, r, e_canal + (e_out - e_canal) * v, 0});
  }
  for (int i = 0; i < kSamples; ++i) {  // up the outside to the fundus pole (excluded)
    const double z = d.length * i / kSamples;
    const auto [a, b] = outer_axes(d, p, z);
    m.push_back({z, a, b, e_out, 0});
  }
  return m;
}

/// Anteflexion: the body above the internal os bent forward (+y) by `angle` over a bend of
/// length `bend` (Barr 1984), as a rigid rotation beyond it. Injective while the bend radius
/// exceeds every |y|.
core::Vec3 bend(const core::Vec3& q, double z0, double bend_length, double angle) {
  const double t = q.z() - z0;
  if (t <= 0.0 || std::abs(angle) < 1e-9) return q;
  const double radius = bend_length / angle;
  const double phi = angle * std::min(t, bend_length) / bend_length;
  const double arm = radius - q.y();
  core::Vec3 out(q.x(), radius - arm * std::cos(phi), z0 + arm * std::sin(phi));
  if (t > bend_length) {
    out += (t - bend_length) * core::Vec3(0.0, std::sin(angle), std::cos(angle));
  }
  return out;
}

double bend_length_of(const UterusDimensions& d) {
  return std::max(0.4 * d.cavity_length, 1.5 * 0.5 * d.thickness * std::abs(d.flexion));
}

}  // namespace

void check_uterus_dimensions(const UterusDimensions& d) {
  const auto fail = [](const std::string& what) { throw core::UsageError("uterus: " + what); };
  for (const double v :
       {d.length, d.width, d.thickness, d.cervix_length, d.cervix_radius, d.canal_radius,
        d.cavity_length, d.cavity_width, d.cavity_depth, d.orifice_radius, d.edge_length}) {
    if (!(v > 0.0)) fail("every dimension must be positive");
  }
  if (d.cervix_radius - 1.2 * d.canal_radius < kMinWall)
    fail("the cervix is too thin around its canal");
  if (d.length - d.cervix_length - d.cavity_length < 1.5 * kMinWall)
    fail("the fundus wall is too thin (length too short for canal and cavity)");
  if (d.orifice_depth > 0.5 * d.orifice_radius || d.orifice_depth < 0.0)
    fail("orifice depth must lie in [0, orifice radius / 2]");
  const Profile p = profile_of(d);
  for (int i = 0; i <= 200; ++i) {
    const double z = p.z_top_in * i / 200.0;
    const auto [ao, bo] = outer_axes(d, p, z);
    const auto [ai, bi] = inner_axes(d, p, z);
    if (ao - ai < kMinWall + d.orifice_depth || bo - bi < kMinWall) {
      fail("the wall is thinner than 4 mm at " + std::to_string(z * 1000.0) +
           " mm above the external os");
    }
  }
  if (bend_length_of(d) / std::max(std::abs(d.flexion), 1e-9) < 0.6 * d.thickness &&
      std::abs(d.flexion) > 1e-9) {
    fail("the flexion bends the body too sharply");
  }
}

UterusShape make_uterus(const UterusDimensions& d, const SmoothDeformation& deformation) {
  check_uterus_dimensions(d);
  const Profile p = profile_of(d);
  const std::vector<MeridianPoint> m = meridian(d, p);

  // Rings about every 0.87 edge lengths along the meridian (near-equilateral triangles).
  std::vector<Ring> rings, outer_rings;
  std::vector<std::uint8_t> ring_region;
  double travelled = 0.0;
  for (std::size_t i = 1; i < m.size(); ++i) {
    travelled += std::hypot(m[i].z - m[i - 1].z,
                            std::max(std::abs(m[i].a - m[i - 1].a), std::abs(m[i].b - m[i - 1].b)));
    if (travelled < 0.87 * m[i].edge && i + 1 != m.size()) continue;
    travelled = 0.0;
    const int count =
        std::max(8, static_cast<int>(std::lround(ellipse_perimeter(m[i].a, m[i].b) / m[i].edge)));
    rings.push_back(ellipse_ring({0.0, 0.0, m[i].z}, core::Vec3::UnitX(), core::Vec3::UnitY(),
                                 m[i].a, m[i].b, count));
    ring_region.push_back(m[i].region);
    if (m[i].region == 0 && m[i].z >= 0.0 && m[i].a >= d.cervix_radius - 1e-12)
      outer_rings.push_back(rings.back());
  }

  UterusShape shape;
  shape.internal_os_height = p.z_io;
  shape.surface = ring_surface({0.0, 0.0, p.z_top_in}, rings, {0.0, 0.0, d.length});
  shape.envelope = ring_surface({0.0, 0.0, 0.0}, outer_rings, {0.0, 0.0, d.length});
  shape.cavity.push_back(1);
  for (std::size_t r = 0; r < rings.size(); ++r)
    shape.cavity.insert(shape.cavity.end(), rings[r].size(), ring_region[r]);
  shape.cavity.push_back(0);

  // Tubal orifices: funnels pushed outwards and upwards into the wall at the cornua.
  std::vector<core::Landmark> marks;
  for (const int side : {1, -1}) {
    const core::Vec3 centre(side * p.half_width_in, 0.0, p.z_cap);
    const core::Vec3 into_wall = core::Vec3(side, 0.0, 0.6).normalized();
    for (auto& v : shape.surface.vertices) {
      const double r = (v - centre).norm() / d.orifice_radius;
      if (r < 1.0) v += into_wall * d.orifice_depth * (1.0 - r * r) * (1.0 - r * r);
    }
    marks.push_back({side > 0 ? "tubal-orifice-left" : "tubal-orifice-right",
                     side > 0 ? "left tubal orifice" : "right tubal orifice", "uterus",
                     centre + into_wall * d.orifice_depth, -into_wall});
  }
  marks.push_back(
      {"fundus", "fundus of the cavity", "uterus", {0.0, 0.0, p.z_top_in}, -core::Vec3::UnitZ()});
  marks.push_back(
      {"cervix-internal-os", "internal os", "uterus", {0.0, 0.0, p.z_io}, core::Vec3::UnitZ()});
  marks.push_back(
      {"cervix-external-os", "external os", "uterus", {0.0, 0.0, 0.0}, -core::Vec3::UnitZ()});

  // Anteflexion, then the random shape field, on surfaces and landmarks alike.
  const double bend_length = bend_length_of(d);
  const auto map = [&](const core::Vec3& q) {
    return deformation.apply(bend(q, p.z_io, bend_length, d.flexion));
  };
  for (auto* mesh : {&shape.surface, &shape.envelope}) {
    for (auto& v : mesh->vertices)
      v = map(v);
  }
  for (auto& mark : marks) {
    const core::Vec3 moved = map(mark.position);
    mark.normal = (map(mark.position + 1e-4 * mark.normal) - moved).normalized();
    mark.position = moved;
  }
  shape.landmarks = std::move(marks);
  core::compute_vertex_normals(shape.surface);
  return shape;
}

}  // namespace viscera::templates
