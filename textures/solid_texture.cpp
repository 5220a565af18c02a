#include "textures/solid_texture.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "core/error.h"
#include "core/lsystem/lsystem.h"
#include "core/random.h"

namespace viscera::textures {
namespace {

using core::Vec3;

// The same seed streams as the flat synthesiser (texture_synthesis.cpp), so a preset and seed
// give the same palette draw and grain field in both.
constexpr std::uint64_t kColorStream = 0, kGrainStream = 1, kWetnessStream = 2, kVesselStream = 16;

double amplitude_sum(int octaves, double persistence) {
  double sum = 0.0, amplitude = 1.0;
  for (int o = 0; o < octaves; ++o, amplitude *= persistence)
    sum += amplitude;
  return sum;
}

}  // namespace

std::vector<std::vector<core::TurtleSegment>> grow_surface_vessels(const TexturePreset& preset,
                                                                   const SurfaceProjector& surface,
                                                                   double texture_scale,
                                                                   std::uint64_t seed) {
  if (!(texture_scale > 0.0)) throw core::UsageError("texture scale must be positive");
  std::vector<std::vector<core::TurtleSegment>> layers;
  for (std::size_t l = 0; l < preset.vessels.size(); ++l) {
    const VesselLayerSpec& spec = preset.vessels[l];
    const core::Lsystem grammar = core::Lsystem::parse(spec.grammar, "vessel grammar");
    const std::uint64_t layer_seed = core::Rng::for_stream(seed, kVesselStream + l).next_u64();
    // As many trees per square texture width as the flat texture has.
    const int trees = static_cast<int>(
        std::lround(spec.trees * surface.area() / (texture_scale * texture_scale)));
    const double step = spec.step * texture_scale, width = spec.width * texture_scale;
    std::vector<core::TurtleSegment> strokes;
    for (int tree = 0; tree < trees; ++tree) {
      core::Rng rng = core::Rng::for_stream(layer_seed, static_cast<std::uint64_t>(tree));
      const SurfacePoint start = surface.random_point(rng);
      const Vec3 tangent = start.normal.unitOrthogonal();
      const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
      core::TurtleOptions turtle;
      turtle.origin = start.point;
      turtle.heading = std::cos(angle) * tangent + std::sin(angle) * start.normal.cross(tangent);
      turtle.left = start.normal.cross(turtle.heading);  // so that up = heading × left = normal
      turtle.angle = spec.angle;
      turtle.angle_jitter = spec.angle_jitter;
      turtle.subdivisions = spec.subdivisions;
      turtle.wiggle = spec.wiggle;
      turtle.width_factor = spec.width_factor;
      turtle.depth_step = spec.depth_step;
      turtle.taper = spec.taper / texture_scale;  // per metre
      turtle.width = width;
      turtle.step = step;
      turtle.constrain = [&surface](Vec3& position, Vec3& heading, Vec3& left, Vec3& up) {
        const SurfacePoint on = surface.closest(position);
        position = on.point;
        up = on.normal;
        const Vec3 along = heading - heading.dot(up) * up;
        if (along.norm() > 1e-12) heading = along.normalized();
        left = up.cross(heading);
      };
      const std::uint64_t derivation_seed = rng.next_u64();
      turtle.seed = rng.next_u64();
      // Grammar lengths and widths are in units of step and width: draw at unit scale by
      // scaling the string's parameters is grammar-specific, so scale the turtle instead.
      const auto modules = grammar.derive(spec.generations, derivation_seed);
      core::LsystemString scaled = modules;
      for (auto& m : scaled) {
        if (m.symbol == 'F' || m.symbol == 'f') {
          if (!m.parameters.empty()) m.parameters[0] *= step;
          if (m.symbol == 'F' && m.parameters.size() > 1) m.parameters[1] *= width;
        } else if (m.symbol == '!' && !m.parameters.empty()) {
          m.parameters[0] *= width;
        }
      }
      const int offset = static_cast<int>(strokes.size());
      for (auto s : core::interpret_turtle(scaled, turtle)) {
        if (s.parent >= 0) s.parent += offset;
        strokes.push_back(s);
      }
    }
    layers.push_back(std::move(strokes));
  }
  return layers;
}

/// Strokes of one layer in a uniform grid, for coverage queries near a point.
struct SolidTissueTexture::VesselIndex {
  std::vector<core::TurtleSegment> strokes;
  double cell = 1.0;
  std::unordered_map<std::uint64_t, std::vector<int>> cells;

  static std::uint64_t key(long long x, long long y, long long z) {
    return (static_cast<std::uint64_t>(x + 1048576) << 42) |
           (static_cast<std::uint64_t>(y + 1048576) << 21) |
           static_cast<std::uint64_t>(z + 1048576);
  }
  long long coordinate(double v) const { return static_cast<long long>(std::floor(v / cell)); }

  explicit VesselIndex(std::vector<core::TurtleSegment> s) : strokes(std::move(s)) {
    double length = 0.0, widest = 0.0;
    for (const auto& st : strokes) {
      length += (st.end - st.start).norm();
      widest = std::max({widest, st.start_width, st.end_width});
    }
    cell = std::max(strokes.empty() ? 1.0 : 2.0 * length / static_cast<double>(strokes.size()),
                    2.0 * widest);
    if (!(cell > 0.0)) cell = 1.0;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
      const auto& st = strokes[i];
      const double pad = 0.5 * std::max(st.start_width, st.end_width) + 0.5 * cell;
      const Vec3 lo = st.start.cwiseMin(st.end) - Vec3::Constant(pad),
                 hi = st.start.cwiseMax(st.end) + Vec3::Constant(pad);
      for (long long x = coordinate(lo.x()); x <= coordinate(hi.x()); ++x)
        for (long long y = coordinate(lo.y()); y <= coordinate(hi.y()); ++y)
          for (long long z = coordinate(lo.z()); z <= coordinate(hi.z()); ++z)
            cells[key(x, y, z)].push_back(static_cast<int>(i));
    }
  }
};

SolidTissueTexture::SolidTissueTexture(const TexturePreset& preset, std::uint64_t seed,
                                       double texture_scale, const Image8* sample,
                                       std::vector<std::vector<core::TurtleSegment>> vessel_layers)
    : preset_(preset),
      scale_(texture_scale),
      colors_(sample ? *sample : palette_sample(preset.palette, preset.palette_weights),
              core::Rng::for_stream(seed, kColorStream).next_u64(), preset.color_octaves,
              preset.color_persistence),
      grain_(core::Rng::for_stream(seed, kGrainStream).next_u64()),
      wetness_(core::Rng::for_stream(seed, kWetnessStream).next_u64()) {
  if (!(texture_scale > 0.0)) throw core::UsageError("texture scale must be positive");
  if (!vessel_layers.empty() && vessel_layers.size() != preset.vessels.size()) {
    throw core::UsageError("one stroke list per vessel layer of the preset is needed");
  }
  for (auto& layer : vessel_layers)
    vessels_.push_back(std::make_unique<VesselIndex>(std::move(layer)));
}

SolidTissueTexture::~SolidTissueTexture() = default;

void SolidTissueTexture::vessel_coverage(const Vec3& p, double texel_size, float* coverage,
                                         float* depth) const {
  for (std::size_t l = 0; l < vessels_.size(); ++l) {
    coverage[l] = 0.0f;
    depth[l] = 0.0f;
    const VesselIndex& index = *vessels_[l];
    const auto it = index.cells.find(VesselIndex::key(
        index.coordinate(p.x()), index.coordinate(p.y()), index.coordinate(p.z())));
    if (it == index.cells.end()) continue;
    for (const int i : it->second) {
      const auto& s = index.strokes[i];
      const Vec3 d = s.end - s.start;
      const double length2 = d.squaredNorm();
      const double t = length2 > 0.0 ? std::clamp((p - s.start).dot(d) / length2, 0.0, 1.0) : 0.0;
      const double distance = (p - (s.start + t * d)).norm();
      const double w = s.start_width + t * (s.end_width - s.start_width);
      // The flat painter's rule in texel units: a one-texel ramp, thin strokes fainter.
      const double footprint = std::max(w, texel_size);
      const auto c =
          static_cast<float>(std::clamp((0.5 * footprint - distance) / texel_size + 0.5, 0.0, 1.0) *
                             std::min(w / texel_size, 1.0));
      if (c > coverage[l] ||
          (c == coverage[l] && c > 0.0f && static_cast<float>(s.depth) < depth[l])) {
        coverage[l] = c;
        depth[l] = static_cast<float>(s.depth);
      }
    }
  }
}

void SolidTissueTexture::texel(const Vec3& p, double texel_size, Rgb& albedo, float& height,
                               float& wetness) const {
  const Vec3 q = p / scale_;  // texture widths
  const Rgb base = colors_.color(q.x() * preset_.color_frequency, q.y() * preset_.color_frequency,
                                 q.z() * preset_.color_frequency);
  const Vec3 g = q * preset_.grain_frequency;
  const double turbulence =
      grain_.turbulence(g.x(), g.y(), g.z(), preset_.grain_octaves, preset_.grain_persistence);
  const Vec3 w = q * preset_.specular_frequency;
  const double wet = wetness_.fractal_sum(w.x(), w.y(), w.z(), 3, 0.5);
  std::vector<float> coverage(vessels_.size()), depth(vessels_.size());
  vessel_coverage(p, texel_size, coverage.data(), depth.data());
  std::vector<const float*> coverage_rows(vessels_.size()), depth_rows(vessels_.size());
  for (std::size_t l = 0; l < vessels_.size(); ++l) {
    coverage_rows[l] = &coverage[l];
    depth_rows[l] = &depth[l];
  }
  TissueFields fields;
  fields.count = 1;
  fields.base_rgb = base.data();
  fields.turbulence = &turbulence;
  fields.turbulence_scale = 1.0 / amplitude_sum(preset_.grain_octaves, preset_.grain_persistence);
  fields.wetness_noise = &wet;
  fields.wetness_scale = 1.0 / amplitude_sum(3, 0.5);
  fields.coverage = vessels_.empty() ? nullptr : coverage_rows.data();
  fields.depth = vessels_.empty() ? nullptr : depth_rows.data();
  shade_tissue(preset_, fields, albedo.data(), &height, &wetness);
}

float SolidTissueTexture::height(const Vec3& p, double texel_size) const {
  const Vec3 g = p / scale_ * preset_.grain_frequency;
  const double turbulence =
      grain_.turbulence(g.x(), g.y(), g.z(), preset_.grain_octaves, preset_.grain_persistence) /
      amplitude_sum(preset_.grain_octaves, preset_.grain_persistence);
  float h = static_cast<float>(preset_.grain_height * turbulence);
  std::vector<float> coverage(vessels_.size()), depth(vessels_.size());
  vessel_coverage(p, texel_size, coverage.data(), depth.data());
  for (std::size_t l = 0; l < vessels_.size(); ++l) {
    h += static_cast<float>(preset_.vessels[l].height) * coverage[l] *
         (1.0f - std::clamp(depth[l], 0.0f, 1.0f));
  }
  return h;
}

SurfaceSample SolidTissueTexture::shade(const Vec3& p, const Vec3& n, double texel_size) const {
  SurfaceSample sample;
  float h = 0.0f;
  texel(p, texel_size, sample.albedo, h, sample.wetness);
  // Forward differences one texel along two tangents: the surface gradient of the height.
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  const double dh1 = static_cast<double>(height(p + texel_size * t1, texel_size) - h) / texel_size;
  const double dh2 = static_cast<double>(height(p + texel_size * t2, texel_size) - h) / texel_size;
  const double k = preset_.normal_strength * scale_;
  sample.normal = (n - k * (dh1 * t1 + dh2 * t2)).normalized();
  return sample;
}

}  // namespace viscera::textures
