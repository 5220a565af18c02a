#include "core/modelling/object_connectivity.h"

#include <cmath>
#include <limits>
#include <set>
#include <unordered_map>

#include "core/error.h"

namespace viscera::core {
namespace {

/// Uniform grid of points with cells of the search radius: a query looks at 27 cells.
class PointGrid {
 public:
  PointGrid(const std::vector<Vec3>& points, double cell) : points_(points), cell_(cell) {
    for (std::size_t i = 0; i < points.size(); ++i)
      cells_[key(cell_of(points[i]))].push_back(static_cast<int>(i));
  }

  /// Index of the nearest point within `radius` (≤ cell) of p, lowest index on ties, or −1.
  int nearest(const Vec3& p, double radius) const {
    const auto c = cell_of(p);
    int best = -1;
    double best_distance = radius * radius;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (const int i : it->second) {
            const double d = (points_[static_cast<std::size_t>(i)] - p).squaredNorm();
            if (d < best_distance || (d == best_distance && best >= 0 && i < best)) {
              best_distance = d;
              best = i;
            }
          }
        }
    return best;
  }

 private:
  std::array<std::int64_t, 3> cell_of(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)),
            static_cast<std::int64_t>(std::floor(p.y() / cell_)),
            static_cast<std::int64_t>(std::floor(p.z() / cell_))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    // The hash primes of Teschner et al. 2003 (DESIGN.md §5); collisions only cost time.
    return static_cast<std::uint64_t>(c[0] * 73856093) ^
           static_cast<std::uint64_t>(c[1] * 19349663) ^
           static_cast<std::uint64_t>(c[2] * 83492791);
  }

  const std::vector<Vec3>& points_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

const SceneObject& find_connectable(const Scenario& scenario, const std::string& id) {
  const SceneObject* object = scenario.find_object(id);
  if (object == nullptr) throw UsageError("there is no object \"" + id + "\" to connect");
  if (object->body.nodes.empty())
    throw UsageError("object \"" + id + "\" has no simulation body whose knots could be connected");
  return *object;
}

}  // namespace

std::vector<std::array<int, 2>> nearest_knot_pairs(const std::vector<Vec3>& a,
                                                   const std::vector<Vec3>& b, double within) {
  if (!(within > 0.0) || !std::isfinite(within))
    throw UsageError("connection distance must be positive");
  std::set<std::array<int, 2>> pairs;
  const PointGrid grid_a(a, within), grid_b(b, within);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int j = grid_b.nearest(a[i], within);
    if (j >= 0) pairs.insert({static_cast<int>(i), j});
  }
  for (std::size_t j = 0; j < b.size(); ++j) {
    const int i = grid_a.nearest(b[j], within);
    if (i >= 0) pairs.insert({i, static_cast<int>(j)});
  }
  return {pairs.begin(), pairs.end()};
}

Connection connect_objects(const Scenario& scenario, const std::string& object_a,
                           const std::string& object_b, double within, double stiffness) {
  if (object_a == object_b)
    throw UsageError("object \"" + object_a + "\" cannot be connected to itself");
  if (!(stiffness > 0.0) || !std::isfinite(stiffness))
    throw UsageError("connection stiffness must be positive");
  const SceneObject& a = find_connectable(scenario, object_a);
  const SceneObject& b = find_connectable(scenario, object_b);
  Connection connection;
  connection.id = object_a + "--" + object_b;
  connection.object_a = object_a;
  connection.object_b = object_b;
  connection.node_pairs = nearest_knot_pairs(a.body.nodes, b.body.nodes, within);
  connection.stiffness = stiffness;
  return connection;
}

void assign_organ_group(Scenario& scenario, const std::string& group,
                        const std::vector<std::string>& object_ids) {
  if (group.empty()) throw UsageError("an organ group needs a name");
  for (const auto& id : object_ids) {
    bool found = false;
    for (auto& object : scenario.objects) {
      if (object.id == id) {
        object.group = group;
        found = true;
      }
    }
    if (!found) throw UsageError("organ group \"" + group + "\" names no object \"" + id + "\"");
  }
}

std::map<std::string, std::vector<std::string>> organ_groups(const Scenario& scenario) {
  std::map<std::string, std::vector<std::string>> groups;
  for (const auto& object : scenario.objects) {
    if (!object.group.empty()) groups[object.group].push_back(object.id);
  }
  return groups;
}

}  // namespace viscera::core
