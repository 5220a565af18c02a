#include "importers/mesh/mesh_integrity.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "core/error.h"

namespace viscera::importers {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PMP = CGAL::Polygon_mesh_processing;

std::string triangle_name(std::size_t t) {
  return "triangle " + std::to_string(t);
}

void check_finite(const core::SurfaceMesh& mesh, const std::string& file) {
  core::check_surface_mesh(mesh, file);
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    if (!mesh.normals[i].allFinite())
      throw core::InputError("normal is not finite", {file, "", "vertex " + std::to_string(i)});
  }
  for (std::size_t i = 0; i < mesh.uvs.size(); ++i) {
    if (!mesh.uvs[i].allFinite()) {
      throw core::InputError("texture coordinate is not finite",
                             {file, "", "vertex " + std::to_string(i)});
    }
  }
}

/// Edges shared by more than two triangles, and vertices whose triangles form several fans.
void check_manifold(const std::vector<core::Triangle>& triangles, std::size_t vertex_count,
                    const std::string& file) {
  std::unordered_map<std::uint64_t, std::vector<int>> edge_faces;
  edge_faces.reserve(triangles.size() * 2);
  const auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint32_t>(std::max(a, b));
  };
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c) {
      auto& faces = edge_faces[key(triangles[t][c], triangles[t][(c + 1) % 3])];
      faces.push_back(static_cast<int>(t));
      if (faces.size() > 2) {
        throw core::InputError(
            "the mesh is not manifold: an edge is shared by more than two triangles (" +
                triangle_name(static_cast<std::size_t>(faces[0])) + ", " +
                triangle_name(static_cast<std::size_t>(faces[1])) + " and " + triangle_name(t) +
                ")",
            {file, "", ""});
      }
    }
  }
  // Fans: around each vertex, join triangles that share an edge through it (union-find over
  // corner slots); more than one group at a vertex is a pinch point.
  std::vector<int> parent(triangles.size() * 3);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[static_cast<std::size_t>(x)] != x)
      x = parent[static_cast<std::size_t>(x)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
  };
  const auto corner_of = [&](int t, int v) {
    for (int c = 0; c < 3; ++c) {
      if (triangles[static_cast<std::size_t>(t)][c] == v) return 3 * t + c;
    }
    return -1;
  };
  for (const auto& [edge, faces] : edge_faces) {
    if (faces.size() != 2) continue;
    for (const int v : {static_cast<int>(edge >> 32), static_cast<int>(edge & 0xffffffffu)}) {
      parent[static_cast<std::size_t>(find(corner_of(faces[0], v)))] = find(corner_of(faces[1], v));
    }
  }
  std::vector<int> group(vertex_count, -1);
  for (std::size_t slot = 0; slot < parent.size(); ++slot) {
    const int v = triangles[slot / 3][slot % 3];
    const int root = find(static_cast<int>(slot));
    int& seen = group[static_cast<std::size_t>(v)];
    if (seen < 0) {
      seen = root;
    } else if (seen != root) {
      throw core::InputError("the mesh is not manifold: the triangles around vertex " +
                                 std::to_string(v) +
                                 " form separate fans (the surface pinches there)",
                             {file, "", ""});
    }
  }
}

void check_self_intersections(const std::vector<core::Vec3>& vertices,
                              const std::vector<core::Triangle>& triangles,
                              const std::string& file) {
  std::vector<Kernel::Point_3> points;
  points.reserve(vertices.size());
  for (const auto& v : vertices)
    points.emplace_back(v.x(), v.y(), v.z());
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(triangles.size());
  for (const auto& t : triangles) {
    polygons.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                        static_cast<std::size_t>(t[2])});
  }
  // Orienting the soup only flips triangles (and duplicates no point: the mesh is manifold
  // here), so face i of the mesh is triangle i of the file.
  PMP::orient_polygon_soup(points, polygons);
  CGAL::Surface_mesh<Kernel::Point_3> mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  using Face = CGAL::Surface_mesh<Kernel::Point_3>::Face_index;
  std::vector<std::pair<Face, Face>> pairs;
  PMP::self_intersections(faces(mesh), mesh, std::back_inserter(pairs),
                          CGAL::parameters::maximum_number(1));
  if (!pairs.empty()) {
    throw core::InputError("the mesh intersects itself: " + triangle_name(pairs.front().first) +
                               " and " + triangle_name(pairs.front().second) + " cross",
                           {file, "", ""});
  }
}

}  // namespace

// Sorting keeps it O(n log n).
std::vector<int> first_copy_by_position(const std::vector<core::Vec3>& vertices) {
  std::vector<int> order(vertices.size());
  std::iota(order.begin(), order.end(), 0);
  const auto less = [&](int a, int b) {
    const auto& p = vertices[static_cast<std::size_t>(a)];
    const auto& q = vertices[static_cast<std::size_t>(b)];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> first(vertices.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int v = order[i];
    first[static_cast<std::size_t>(v)] =
        i > 0 && vertices[static_cast<std::size_t>(order[i - 1])] ==
                     vertices[static_cast<std::size_t>(v)]
            ? first[static_cast<std::size_t>(order[i - 1])]
            : v;
  }
  return first;
}

void join_identical_vertices(core::SurfaceMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  const auto key = [&](std::size_t v) {
    std::array<double, 8> k{};
    for (int c = 0; c < 3; ++c)
      k[static_cast<std::size_t>(c)] = mesh.vertices[v][c];
    for (int c = 0; c < 3 && !mesh.normals.empty(); ++c)
      k[static_cast<std::size_t>(3 + c)] = mesh.normals[v][c];
    for (int c = 0; c < 2 && !mesh.uvs.empty(); ++c)
      k[static_cast<std::size_t>(6 + c)] = mesh.uvs[v][c];
    return k;
  };
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto ka = key(a), kb = key(b);
    return ka != kb ? ka < kb : a < b;
  });
  std::vector<std::size_t> first(n);
  for (std::size_t i = 0; i < n; ++i) {
    first[order[i]] = i > 0 && key(order[i - 1]) == key(order[i]) ? first[order[i - 1]] : order[i];
  }
  std::vector<int> index(n, -1);
  core::SurfaceMesh joined;
  for (std::size_t v = 0; v < n; ++v) {
    if (first[v] != v) continue;
    index[v] = static_cast<int>(joined.vertices.size());
    joined.vertices.push_back(mesh.vertices[v]);
    if (!mesh.normals.empty()) joined.normals.push_back(mesh.normals[v]);
    if (!mesh.uvs.empty()) joined.uvs.push_back(mesh.uvs[v]);
  }
  for (const auto& t : mesh.triangles) {
    core::Triangle j;
    for (int c = 0; c < 3; ++c)
      j[c] = index[first[static_cast<std::size_t>(t[c])]];
    joined.triangles.push_back(j);
  }
  mesh = std::move(joined);
}

void check_surface_integrity(const core::SurfaceMesh& mesh, const std::string& file) {
  check_finite(mesh, file);
  const std::vector<int> weld = first_copy_by_position(mesh.vertices);
  std::vector<core::Triangle> welded;
  welded.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const core::Triangle w = {weld[static_cast<std::size_t>(tri[0])],
                              weld[static_cast<std::size_t>(tri[1])],
                              weld[static_cast<std::size_t>(tri[2])]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) {
      throw core::InputError("triangle has two corners at the same position",
                             {file, "", triangle_name(t)});
    }
    const auto p = [&](int v) {
      const auto& x = mesh.vertices[static_cast<std::size_t>(v)];
      return Kernel::Point_3(x.x(), x.y(), x.z());
    };
    if (CGAL::collinear(p(w[0]), p(w[1]), p(w[2]))) {
      throw core::InputError("triangle is degenerate: its corners lie on one line",
                             {file, "", triangle_name(t)});
    }
    welded.push_back(w);
  }
  check_manifold(welded, mesh.vertices.size(), file);
  check_self_intersections(mesh.vertices, welded, file);
}

std::vector<core::Triangle> checked_boundary_faces(const core::TetMesh& mesh,
                                                   const std::string& file) {
  // The faces of a positively oriented tet (a,b,c,d), counter-clockwise from outside (as core).
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  struct Face {
    std::array<int, 3> key;  ///< sorted corners
    core::Triangle face;
    std::size_t tet;
  };
  std::vector<Face> faces;
  faces.reserve(4 * mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (const auto& f : kFaces) {
      Face face{{}, {mesh.tets[t][f[0]], mesh.tets[t][f[1]], mesh.tets[t][f[2]]}, t};
      face.key = face.face;
      std::sort(face.key.begin(), face.key.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
    return a.key != b.key ? a.key < b.key : a.tet < b.tet;
  });
  std::vector<core::Triangle> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t end = i + 1;
    while (end < faces.size() && faces[end].key == faces[i].key)
      ++end;
    if (end - i > 2) {
      throw core::InputError(
          "the mesh is not manifold: a face is shared by more than two tetrahedra",
          {file, "", "tet " + std::to_string(faces[i + 2].tet)});
    }
    if (end - i == 1) boundary.push_back(faces[i].face);
    i = end;
  }
  return boundary;
}

}  // namespace viscera::importers
