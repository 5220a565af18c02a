#include "templates/generator/diversity_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/package/vtk_mesh_io.h"

namespace viscera::templates {
namespace {

constexpr std::size_t kSamples = 500;
constexpr std::size_t kMaxPairs = 1000;

/// Mean over strided samples of `a` of the distance to the nearest vertex of `b`.
double directed_mean(const std::vector<core::Vec3>& a, const std::vector<core::Vec3>& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  const std::size_t stride = std::max<std::size_t>(1, a.size() / kSamples);
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); i += stride, ++n) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& q : b)
      best = std::min(best, (a[i] - q).squaredNorm());
    sum += std::sqrt(best);
  }
  return sum / static_cast<double>(n);
}

}  // namespace

nlohmann::json parameter_histograms(const ScenarioTemplate& scenario_template,
                                    const std::vector<core::VariabilityRule>& rules,
                                    const nlohmann::json& records) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& p : scenario_template.parameters()) {
    const bool varied = std::any_of(rules.begin(), rules.end(), [&](const auto& r) {
      return r.parameter == p.name && r.distribution != "fixed";
    });
    if (!varied) continue;
    std::vector<double> values;
    for (const auto& r : records)
      values.push_back(r.at("parameters").at(p.name).get<double>());
    std::vector<double> edges;
    const double span = p.maximum - p.minimum;
    if (p.integer && span <= 20.0) {
      for (double v = p.minimum; v <= p.maximum + 1.0; v += 1.0)
        edges.push_back(v - 0.5);
    } else {
      for (int i = 0; i <= 10; ++i)
        edges.push_back(p.minimum + span * i / 10.0);
    }
    std::vector<int> counts(edges.size() - 1, 0);
    double sum = 0.0, lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double v : values) {
      sum += v;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      auto bin =
          static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), v) - edges.begin());
      bin = std::clamp<std::size_t>(bin, 1, counts.size()) - 1;
      ++counts[bin];
    }
    const double mean = values.empty() ? 0.0 : sum / static_cast<double>(values.size());
    double squares = 0.0;
    for (const double v : values)
      squares += (v - mean) * (v - mean);
    out[p.name] = {
        {"unit", p.unit},
        {"count", values.size()},
        {"mean", mean},
        {"stddev",
         values.size() > 1 ? std::sqrt(squares / static_cast<double>(values.size() - 1)) : 0.0},
        {"min", values.empty() ? 0.0 : lo},
        {"max", values.empty() ? 0.0 : hi},
        {"bin_edges", edges},
        {"counts", counts}};
  }
  return out;
}

nlohmann::json shape_distances(const nlohmann::json& records, const std::filesystem::path& folder) {
  std::vector<std::vector<core::Vec3>> surfaces;
  for (const auto& r : records) {
    core::SurfaceMesh surface;
    core::SurfaceEmbedding embedding;
    core::read_surface_vtp(folder / r.at("package").get<std::string>() / "objects" /
                               r.at("organ").get<std::string>() / "surface.vtp",
                           surface, embedding);
    surfaces.push_back(std::move(surface.vertices));
  }
  const std::size_t n = surfaces.size();
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (n * (n - (n > 0 ? 1 : 0)) / 2 <= kMaxPairs) {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        pairs.emplace_back(i, j);
  } else {
    const std::size_t ahead = (kMaxPairs + n - 1) / n;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t s = 1; s <= ahead; ++s)
        pairs.emplace_back(i, (i + s) % n);
  }
  std::vector<double> distances;
  double best = std::numeric_limits<double>::infinity();
  std::pair<std::size_t, std::size_t> closest{0, 0};
  int identical = 0;
  for (const auto& [i, j] : pairs) {
    const double d =
        0.5 * (directed_mean(surfaces[i], surfaces[j]) + directed_mean(surfaces[j], surfaces[i]));
    distances.push_back(d);
    if (d == 0.0) ++identical;
    if (d < best) best = d, closest = {i, j};
  }
  nlohmann::json out = {
      {"measure",
       "symmetric mean closest-point distance between the primary organs' surface vertices (up "
       "to 500 strided samples against all vertices), template frame, no registration"},
      {"unit", "m"},
      {"pairs", distances.size()},
      {"identical_pairs", identical}};
  if (distances.empty()) return out;
  std::vector<double> sorted = distances;
  std::sort(sorted.begin(), sorted.end());
  double sum = 0.0;
  for (const double d : sorted)
    sum += d;
  const std::size_t m = sorted.size();
  out["min"] = sorted.front();
  out["max"] = sorted.back();
  out["mean"] = sum / static_cast<double>(m);
  out["median"] = m % 2 == 1 ? sorted[m / 2] : 0.5 * (sorted[m / 2 - 1] + sorted[m / 2]);
  out["closest_pair"] = {records[closest.first].at("index"), records[closest.second].at("index")};
  return out;
}

}  // namespace viscera::templates
