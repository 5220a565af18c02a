#include "core/modelling/layered_body.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/error.h"

namespace viscera::core {

std::string to_string(LayerMode mode) {
  return mode == LayerMode::Scale ? "scale" : "offset";
}

LayerMode layer_mode_from_string(const std::string& name) {
  if (name == "offset") return LayerMode::Offset;
  if (name == "scale") return LayerMode::Scale;
  throw UsageError("layer mode must be offset or scale, not \"" + name + "\"");
}

namespace {

Vec3 face_normal(const std::vector<Vec3>& p, const Triangle& t) {
  return (p[static_cast<std::size_t>(t[1])] - p[static_cast<std::size_t>(t[0])])
      .cross(p[static_cast<std::size_t>(t[2])] - p[static_cast<std::size_t>(t[0])]);
}

/// Boundary edges a → b of an open surface, in the direction its triangles use them.
std::vector<std::array<int, 2>> border_edges(const SurfaceMesh& surface) {
  std::set<std::pair<int, int>> directed;
  for (const auto& t : surface.triangles)
    for (int e = 0; e < 3; ++e)
      directed.insert({t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]});
  std::vector<std::array<int, 2>> border;
  for (const auto& [a, b] : directed) {
    if (!directed.contains({b, a})) border.push_back({a, b});
  }
  return border;
}

double mean_edge_length(const SurfaceMesh& surface) {
  double total = 0.0;
  for (const auto& t : surface.triangles)
    for (int e = 0; e < 3; ++e)
      total +=
          (surface.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(e)])] -
           surface.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>((e + 1) % 3)])])
              .norm();
  return total / (3.0 * static_cast<double>(std::max<std::size_t>(1, surface.triangles.size())));
}

}  // namespace

std::vector<std::vector<Vec3>> layer_positions(const SurfaceMesh& surface,
                                               const LayerOptions& options) {
  check_surface_mesh(surface, "surface to layer");
  if (surface.triangles.empty()) throw UsageError("the surface to layer has no triangles");
  if (options.layers < 1 || options.layers > 64) throw UsageError("layer count must be in [1, 64]");
  if (!(options.thickness > 0.0) || !std::isfinite(options.thickness))
    throw UsageError("layer thickness must be positive");
  const std::size_t n = surface.vertices.size();
  std::vector<std::vector<Vec3>> layers(static_cast<std::size_t>(options.layers) + 1,
                                        surface.vertices);
  if (options.mode == LayerMode::Offset) {
    SurfaceMesh normals_of{surface.vertices, surface.triangles, {}, {}, {}};
    compute_vertex_normals(normals_of);
    for (int l = 1; l <= options.layers; ++l) {
      const double depth = options.thickness * l / options.layers;
      for (std::size_t i = 0; i < n; ++i)
        layers[static_cast<std::size_t>(l)][i] -= depth * normals_of.normals[i];
    }
  } else {
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& p : surface.vertices)
      centroid += p / static_cast<double>(n);
    double mean_radius = 0.0;
    for (const Vec3& p : surface.vertices)
      mean_radius += (p - centroid).norm() / static_cast<double>(n);
    if (!(options.thickness < mean_radius)) {
      throw UsageError("layer thickness " + std::to_string(options.thickness) +
                       " m reaches the centre of the surface (mean radius " +
                       std::to_string(mean_radius) + " m)");
    }
    for (int l = 1; l <= options.layers; ++l) {
      const double scale = 1.0 - options.thickness / mean_radius * l / options.layers;
      for (std::size_t i = 0; i < n; ++i)
        layers[static_cast<std::size_t>(l)][i] =
            centroid + scale * (surface.vertices[i] - centroid);
    }
  }
  // A copy folds where a triangle turns over or collapses.
  for (int l = 1; l <= options.layers; ++l) {
    for (const auto& t : surface.triangles) {
      const Vec3 original = face_normal(surface.vertices, t),
                 copy = face_normal(layers[static_cast<std::size_t>(l)], t);
      if (!(copy.dot(original) > 1e-3 * original.squaredNorm())) {
        throw UsageError("layer " + std::to_string(l) + " folds near vertex " +
                         std::to_string(t[0]) +
                         ": the thickness exceeds what the surface's curvature allows there");
      }
    }
  }
  return layers;
}

MassSpringNet layered_mass_spring_net(const SurfaceMesh& surface, const LayerOptions& options) {
  const auto layers = layer_positions(surface, options);
  MassSpringNet net;
  net.knots_per_layer = static_cast<int>(surface.vertices.size());
  net.layer_count = static_cast<int>(layers.size());
  for (const auto& layer : layers)
    net.knots.insert(net.knots.end(), layer.begin(), layer.end());
  const int n = net.knots_per_layer;
  for (int l = 0; l + 1 < net.layer_count; ++l) {
    for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
      // Rotate the triangle (keeping its turn) so that its smallest index comes first; the
      // inner copy of knot k is k + n.
      Triangle t = surface.triangles[f];
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      const int v0 = l * n + t[0], v1 = l * n + t[1], v2 = l * n + t[2];
      const int v3 = v0 + n, v4 = v1 + n, v5 = v2 + n;
      // Quad diagonals from each face's smallest knot: v0–v4 and v0–v5 always, and v1–v5 or
      // v2–v4 on the third face.
      const std::array<Tetrahedron, 3> prism =
          v1 < v2
              ? std::array<Tetrahedron, 3>{{{v0, v1, v2, v5}, {v0, v1, v5, v4}, {v0, v4, v5, v3}}}
              : std::array<Tetrahedron, 3>{{{v0, v1, v2, v4}, {v0, v4, v2, v5}, {v0, v4, v5, v3}}};
      for (const Tetrahedron& tet : prism) {
        // With the outer triangle counter-clockwise from outside and the copy inside, every
        // tet of an intact prism has negative volume in this order.
        const double volume = signed_volume(net.knots[static_cast<std::size_t>(tet[0])],
                                            net.knots[static_cast<std::size_t>(tet[1])],
                                            net.knots[static_cast<std::size_t>(tet[2])],
                                            net.knots[static_cast<std::size_t>(tet[3])]);
        if (!(volume < 0.0)) {
          throw UsageError("the prism under triangle " + std::to_string(f) + " between layers " +
                           std::to_string(l) + " and " + std::to_string(l + 1) +
                           " is inverted: the layers are too thick for the surface there");
        }
        net.tets.push_back({tet[0], tet[1], tet[3], tet[2]});
      }
    }
  }
  std::set<std::array<int, 2>> edges;
  for (const auto& tet : net.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        edges.insert(
            {std::min(tet[static_cast<std::size_t>(a)], tet[static_cast<std::size_t>(b)]),
             std::max(tet[static_cast<std::size_t>(a)], tet[static_cast<std::size_t>(b)])});
      }
  for (const auto& e : edges) {
    net.springs.push_back(e);
    net.rest_length.push_back(
        (net.knots[static_cast<std::size_t>(e[1])] - net.knots[static_cast<std::size_t>(e[0])])
            .norm());
  }
  return net;
}

TetMesh mass_spring_body(const MassSpringNet& net) {
  TetMesh body;
  body.nodes = net.knots;
  body.tets = net.tets;
  body.surface_faces = boundary_faces(net.tets);
  return body;
}

TetMesh layered_shell_tets(const SurfaceMesh& surface, const LayerOptions& options,
                           TetMeshingOptions meshing, Progress& progress) {
  const auto layers = layer_positions(surface, options);
  const std::size_t n = surface.vertices.size();
  if (!(meshing.cell_size > 0.0))
    meshing.cell_size = std::min(mean_edge_length(surface), options.thickness / options.layers);
  const SurfaceMesh outer{surface.vertices, surface.triangles, {}, {}, {}};
  const SurfaceMesh inner{layers.back(), surface.triangles, {}, {}, {}};
  if (is_closed_and_consistently_oriented(outer))
    return mesh_region_between(outer, {inner}, meshing, progress);

  // An open sheet: close the slab between the sheet and its copy with a rim along the border.
  SurfaceMesh slab = outer;
  slab.vertices.insert(slab.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  const int offset = static_cast<int>(n);
  for (const auto& t : surface.triangles)
    slab.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  for (const auto& [a, b] : border_edges(surface)) {
    slab.triangles.push_back({a, b + offset, b});
    slab.triangles.push_back({a, a + offset, b + offset});
  }
  return mesh_closed_surface(slab, meshing, progress);
}

SurfaceEmbedding embed_leading_nodes(const TetMesh& body, std::size_t count) {
  std::vector<int> tet_of(count, -1);
  std::vector<int> slot_of(count, 0);
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    for (int c = 0; c < 4; ++c) {
      const auto node = static_cast<std::size_t>(body.tets[t][static_cast<std::size_t>(c)]);
      if (node < count && tet_of[node] < 0) {
        tet_of[node] = static_cast<int>(t);
        slot_of[node] = c;
      }
    }
  }
  SurfaceEmbedding embedding;
  for (std::size_t i = 0; i < count; ++i) {
    if (tet_of[i] < 0)
      throw InputError("surface vertex is in no tetrahedron of the body",
                       {"", "", "vertex " + std::to_string(i)});
    embedding.tet.push_back(tet_of[i]);
    std::array<double, 4> weights{0.0, 0.0, 0.0, 0.0};
    weights[static_cast<std::size_t>(slot_of[i])] = 1.0;
    embedding.weights.push_back(weights);
  }
  return embedding;
}

}  // namespace viscera::core
