#include "textures/uv_charts.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace viscera::textures {
namespace {

using Edge = std::pair<int, int>;

Edge undirected(int a, int b) {
  return a < b ? Edge{a, b} : Edge{b, a};
}

/// Triangles across each edge of each triangle (−1 at borders and non-manifold edges).
std::vector<std::array<int, 3>> triangle_neighbours(const core::SurfaceMesh& mesh) {
  std::map<Edge, std::vector<int>> edge_faces;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      edge_faces[undirected(mesh.triangles[t][e], mesh.triangles[t][(e + 1) % 3])].push_back(
          static_cast<int>(t));
    }
  }
  std::vector<std::array<int, 3>> neighbours(mesh.triangles.size(), {-1, -1, -1});
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      const auto& faces =
          edge_faces[undirected(mesh.triangles[t][e], mesh.triangles[t][(e + 1) % 3])];
      if (faces.size() == 2)
        neighbours[t][e] = faces[0] == static_cast<int>(t) ? faces[1] : faces[0];
    }
  }
  return neighbours;
}

/// Splits `triangles` (connected) into two connected halves along the longest axis of their
/// centroids' bounding box, by growing from the extreme triangle until half the area is taken.
std::pair<std::vector<int>, std::vector<int>> split_in_two(
    const core::SurfaceMesh& mesh, const std::vector<int>& triangles,
    const std::vector<std::array<int, 3>>& neighbours) {
  core::BoundingBox box;
  std::vector<core::Vec3> centroid(triangles.size());
  double total = 0.0;
  std::vector<double> area(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = mesh.triangles[triangles[i]];
    centroid[i] = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    area[i] = 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                        .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                        .norm();
    total += area[i];
    box.add(centroid[i]);
  }
  int axis = 0;
  box.size().maxCoeff(&axis);
  std::map<int, std::size_t> local;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    local[triangles[i]] = i;
  std::size_t seed = 0;
  for (std::size_t i = 1; i < triangles.size(); ++i) {
    if (centroid[i][axis] < centroid[seed][axis]) seed = i;
  }
  // Grow by ascending coordinate from the extreme triangle: a sweep that stays connected.
  std::vector<bool> taken(triangles.size(), false);
  std::set<std::pair<double, std::size_t>> front = {{centroid[seed][axis], seed}};
  double grown = 0.0;
  while (!front.empty() && grown < 0.5 * total) {
    const auto [key, i] = *front.begin();
    front.erase(front.begin());
    if (taken[i]) continue;
    taken[i] = true;
    grown += area[i];
    for (const int n : neighbours[triangles[i]]) {
      const auto it = local.find(n);
      if (n >= 0 && it != local.end() && !taken[it->second])
        front.insert({centroid[it->second][axis], it->second});
    }
  }
  std::pair<std::vector<int>, std::vector<int>> halves;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    (taken[i] ? halves.first : halves.second).push_back(triangles[i]);
  return halves;
}

/// Connected components of `triangles` over shared manifold edges.
std::vector<std::vector<int>> components(const std::vector<int>& triangles,
                                         const std::vector<std::array<int, 3>>& neighbours) {
  std::set<int> remaining(triangles.begin(), triangles.end());
  std::vector<std::vector<int>> parts;
  while (!remaining.empty()) {
    std::vector<int> part, stack = {*remaining.begin()};
    remaining.erase(remaining.begin());
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      part.push_back(t);
      for (const int n : neighbours[t]) {
        if (n >= 0 && remaining.erase(n)) stack.push_back(n);
      }
    }
    std::sort(part.begin(), part.end());
    parts.push_back(std::move(part));
  }
  return parts;
}

}  // namespace

bool is_topological_disk(const core::SurfaceMesh& mesh, const std::vector<int>& triangles) {
  std::set<int> vertices;
  std::map<Edge, int> edges;
  std::map<std::pair<int, int>, int> directed;
  for (const int t : triangles) {
    for (int e = 0; e < 3; ++e) {
      const int a = mesh.triangles[t][e], b = mesh.triangles[t][(e + 1) % 3];
      vertices.insert(a);
      ++edges[undirected(a, b)];
      ++directed[{a, b}];
    }
  }
  // Manifold and consistently oriented inside the chart.
  for (const auto& [edge, count] : edges) {
    if (count > 2) return false;
  }
  for (const auto& [edge, count] : directed) {
    if (count > 1) return false;
  }
  const long euler = static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) +
                     static_cast<long>(triangles.size());
  if (euler != 1) return false;
  // Exactly one boundary loop, and no vertex where the boundary touches itself.
  std::map<int, int> boundary_next;
  for (const auto& [edge, count] : directed) {
    if (!directed.contains({edge.second, edge.first})) {
      if (boundary_next.contains(edge.first)) return false;
      boundary_next[edge.first] = edge.second;
    }
  }
  if (boundary_next.empty()) return false;
  std::size_t loop = 0;
  int v = boundary_next.begin()->first;
  do {
    v = boundary_next[v];
    ++loop;
  } while (v != boundary_next.begin()->first && loop <= boundary_next.size());
  return loop == boundary_next.size();
}

ChartSegmentation segment_charts(const core::SurfaceMesh& mesh, int smoothing_passes) {
  const auto neighbours = triangle_neighbours(mesh);
  const std::size_t n = mesh.triangles.size();
  std::vector<core::Vec3> normal(n);
  std::vector<int> label(n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    normal[t] = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                    .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]])
                    .normalized();
    if (!normal[t].allFinite()) normal[t] = core::Vec3::UnitZ();
    int axis = 0;
    normal[t].cwiseAbs().maxCoeff(&axis);
    label[t] = 2 * axis + (normal[t][axis] < 0 ? 1 : 0);
  }
  const auto axis_dot = [&](std::size_t t, int l) {
    return (l % 2 ? -1.0 : 1.0) * normal[t][l / 2];
  };
  for (int pass = 0; pass < smoothing_passes; ++pass) {
    std::vector<int> next = label;
    for (std::size_t t = 0; t < n; ++t) {
      // A triangle surrounded on two or three sides by one other chart joins it, if its normal
      // still leans towards that chart's axis: seams lose their one-triangle teeth.
      for (const int candidate : {neighbours[t][0] >= 0 ? label[neighbours[t][0]] : -1,
                                  neighbours[t][1] >= 0 ? label[neighbours[t][1]] : -1}) {
        if (candidate < 0 || candidate == label[t]) continue;
        int votes = 0;
        for (const int nb : neighbours[t])
          votes += nb >= 0 && label[nb] == candidate;
        if (votes >= 2 && axis_dot(t, candidate) > 0.3) next[t] = candidate;
      }
    }
    label = std::move(next);
  }
  // Connected components of each label, split until every chart is a disk.
  std::map<int, std::vector<int>> by_label;
  for (std::size_t t = 0; t < n; ++t)
    by_label[label[t]].push_back(static_cast<int>(t));
  std::vector<std::vector<int>> pending, charts;
  for (const auto& [l, triangles] : by_label) {
    for (auto& part : components(triangles, neighbours))
      pending.push_back(std::move(part));
  }
  while (!pending.empty()) {
    std::vector<int> chart = std::move(pending.back());
    pending.pop_back();
    if (chart.size() == 1 || is_topological_disk(mesh, chart)) {
      charts.push_back(std::move(chart));
      continue;
    }
    auto [a, b] = split_in_two(mesh, chart, neighbours);
    for (auto* half : {&a, &b}) {
      for (auto& part : components(*half, neighbours))
        pending.push_back(std::move(part));
    }
  }
  // A stable order: by smallest triangle index.
  std::sort(charts.begin(), charts.end(),
            [](const auto& x, const auto& y) { return x.front() < y.front(); });
  ChartSegmentation result;
  result.chart_of_triangle.assign(n, -1);
  result.chart_count = static_cast<int>(charts.size());
  for (std::size_t c = 0; c < charts.size(); ++c) {
    for (const int t : charts[c])
      result.chart_of_triangle[t] = static_cast<int>(c);
  }
  return result;
}

}  // namespace viscera::textures
