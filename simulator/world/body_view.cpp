#include "simulator/world/body_view.h"

#include <algorithm>

namespace viscera::sim {

std::size_t BodyView::edge_count() const {
  std::vector<std::array<int, 2>> edges;
  for (const auto& t : tets())
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        edges.push_back({std::min(t[a], t[b]), std::max(t[a], t[b])});
  std::sort(edges.begin(), edges.end());
  return static_cast<std::size_t>(std::unique(edges.begin(), edges.end()) - edges.begin());
}

double BodyView::max_displacement() const {
  const auto x = positions();
  const auto rest = rest_positions();
  double largest = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    largest = std::max(largest, (x[i] - rest[i]).norm());
  return largest;
}

namespace {

Vec3 weighted_centre(std::span<const Vec3> x, std::span<const double> mass) {
  Vec3 sum = Vec3::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sum += mass[i] * x[i];
    total += mass[i];
  }
  return total > 0.0 ? Vec3(sum / total) : sum;
}

}  // namespace

Vec3 BodyView::centre_of_mass() const {
  return weighted_centre(positions(), masses());
}

Vec3 BodyView::rest_centre_of_mass() const {
  return weighted_centre(rest_positions(), masses());
}

}  // namespace viscera::sim
