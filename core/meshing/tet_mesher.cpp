#include "core/meshing/tet_mesher.h"

#include <gmsh.h>

#include <map>
#include <mutex>

#include "core/error.h"

namespace viscera::core {
namespace {

/// gmsh is one global model per process: one session at a time, finalised on every path.
class GmshSession {
 public:
  GmshSession() : lock_(mutex()) {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::option::setNumber("General.NumThreads", 1);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex instance;
    return instance;
  }
  std::lock_guard<std::mutex> lock_;
};

/// Mean edge length of the boundaries' triangles, m.
double mean_edge_length(const std::vector<const SurfaceMesh*>& boundaries) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const SurfaceMesh* boundary : boundaries) {
    for (const auto& t : boundary->triangles) {
      for (int e = 0; e < 3; ++e)
        sum += (boundary->vertices[t[e]] - boundary->vertices[t[(e + 1) % 3]]).norm();
      count += 3;
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

/// The graded size field: distance to the boundary nodes, thresholded from surface_size at the
/// surface to cell_size at grading_distance; it replaces the sizes gmsh would take from the
/// boundary so that the grading is the field's alone.
void add_size_field(const TetMeshingOptions& options, const std::vector<int>& surface_tags,
                    double surface_size) {
  const int distance = gmsh::model::mesh::field::add("Distance");
  std::vector<double> surfaces(surface_tags.begin(), surface_tags.end());
  gmsh::model::mesh::field::setNumbers(distance, "SurfacesList", surfaces);
  const int threshold = gmsh::model::mesh::field::add("Threshold");
  gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
  gmsh::model::mesh::field::setNumber(threshold, "SizeMin", surface_size);
  gmsh::model::mesh::field::setNumber(threshold, "SizeMax", options.cell_size);
  gmsh::model::mesh::field::setNumber(threshold, "DistMin", 0.0);
  gmsh::model::mesh::field::setNumber(threshold, "DistMax", options.grading_distance);
  gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

constexpr int kTriangle3 = 2;     // gmsh element type of 3-node triangles
constexpr int kTetrahedron4 = 4;  // gmsh element type of 4-node tetrahedra

}  // namespace

TetMesh mesh_closed_surface(const SurfaceMesh& surface, const TetMeshingOptions& options,
                            Progress& progress) {
  return mesh_region_between(surface, {}, options, progress);
}

TetMesh mesh_region_between(const SurfaceMesh& outer, const std::vector<SurfaceMesh>& holes,
                            const TetMeshingOptions& options, Progress& progress) {
  std::vector<const SurfaceMesh*> boundaries = {&outer};
  for (const auto& hole : holes)
    boundaries.push_back(&hole);
  for (std::size_t b = 0; b < boundaries.size(); ++b) {
    const std::string what = b == 0 ? "surface to mesh" : "inner surface " + std::to_string(b);
    check_surface_mesh(*boundaries[b], what);
    if (!is_closed_and_consistently_oriented(*boundaries[b])) {
      throw InputError(what + " is not closed and consistently oriented; cannot fill it with tets");
    }
    if (enclosed_volume(*boundaries[b]) <= 0.0) {
      throw InputError(what + " encloses no positive volume (inward-facing triangles?)");
    }
  }
  if (!(options.grading_distance >= 0.0) || !(options.surface_size >= 0.0) ||
      !(options.optimize_threshold >= 0.0 && options.optimize_threshold <= 1.0)) {
    throw UsageError(
        "grading distance and surface size must be ≥ 0 and the optimisation threshold in [0, 1]");
  }
  progress.begin_stage("tetrahedral meshing", 3);

  GmshSession session;
  TetMesh result;
  try {
    gmsh::model::add("viscera");
    gmsh::option::setNumber("Mesh.RandomSeed", options.random_seed);
    gmsh::option::setNumber("Mesh.Optimize", options.optimize ? 1 : 0);
    gmsh::option::setNumber("Mesh.OptimizeThreshold", options.optimize_threshold);
    gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay
    if (options.cell_size > 0.0) {
      gmsh::option::setNumber("Mesh.MeshSizeMax", options.cell_size);
    }

    // One discrete surface per boundary, node and element tags numbered on across them, and
    // one surface loop each: the first bounds the volume, the others are its holes.
    std::vector<int> loops, surface_tags;
    std::size_t node_offset = 0, element_offset = 0;
    for (const SurfaceMesh* boundary : boundaries) {
      const int surface_tag = gmsh::model::addDiscreteEntity(2);
      surface_tags.push_back(surface_tag);
      std::vector<std::size_t> node_tags(boundary->vertices.size());
      std::vector<double> coordinates;
      coordinates.reserve(3 * boundary->vertices.size());
      for (std::size_t i = 0; i < boundary->vertices.size(); ++i) {
        node_tags[i] = node_offset + i + 1;
        for (int c = 0; c < 3; ++c)
          coordinates.push_back(boundary->vertices[i][c]);
      }
      gmsh::model::mesh::addNodes(2, surface_tag, node_tags, coordinates);
      std::vector<std::size_t> element_tags(boundary->triangles.size());
      std::vector<std::size_t> element_nodes;
      element_nodes.reserve(3 * boundary->triangles.size());
      for (std::size_t t = 0; t < boundary->triangles.size(); ++t) {
        element_tags[t] = element_offset + t + 1;
        for (const int v : boundary->triangles[t])
          element_nodes.push_back(node_offset + static_cast<std::size_t>(v) + 1);
      }
      gmsh::model::mesh::addElementsByType(surface_tag, kTriangle3, element_tags, element_nodes);
      // A built-in-kernel volume bounded by the discrete surfaces: gmsh keeps the surface
      // triangles as they are and fills the inside.
      loops.push_back(gmsh::model::geo::addSurfaceLoop({surface_tag}));
      node_offset += boundary->vertices.size();
      element_offset += boundary->triangles.size();
    }
    const int volume_tag = gmsh::model::geo::addVolume(loops);
    gmsh::model::geo::synchronize();
    if (options.grading_distance > 0.0 && options.cell_size > 0.0) {
      add_size_field(
          options, surface_tags,
          options.surface_size > 0.0 ? options.surface_size : mean_edge_length(boundaries));
    }
    progress.step();

    gmsh::model::mesh::generate(3);
    progress.step();

    std::vector<std::size_t> all_tags;
    std::vector<double> all_coordinates, parametric;
    gmsh::model::mesh::getNodes(all_tags, all_coordinates, parametric, -1, -1, true, false);
    // gmsh numbers nodes by tag; map tags to dense indices, keeping the boundaries' own
    // vertices first and in their order so surface_faces reuse the input triangles.
    std::map<std::size_t, int> index_of_tag;
    for (const SurfaceMesh* boundary : boundaries) {
      for (const Vec3& v : boundary->vertices) {
        index_of_tag[result.nodes.size() + 1] = static_cast<int>(result.nodes.size());
        result.nodes.push_back(v);
      }
    }
    for (std::size_t i = 0; i < all_tags.size(); ++i) {
      if (index_of_tag.contains(all_tags[i])) continue;
      index_of_tag[all_tags[i]] = static_cast<int>(result.nodes.size());
      result.nodes.emplace_back(all_coordinates[3 * i], all_coordinates[3 * i + 1],
                                all_coordinates[3 * i + 2]);
    }
    std::vector<std::size_t> tet_tags, tet_nodes;
    gmsh::model::mesh::getElementsByType(kTetrahedron4, tet_tags, tet_nodes, volume_tag);
    result.tets.resize(tet_tags.size());
    for (std::size_t t = 0; t < tet_tags.size(); ++t) {
      for (int c = 0; c < 4; ++c)
        result.tets[t][c] = index_of_tag.at(tet_nodes[4 * t + c]);
    }
  } catch (const std::string& gmsh_message) {
    // gmsh 4.8 throws std::string (BUILD_NOTES.md).
    throw InputError("gmsh could not mesh the surface: " + gmsh_message);
  } catch (const std::out_of_range&) {
    throw InputError("gmsh returned a tetrahedron with an unknown node");
  }
  if (result.tets.empty()) {
    throw InputError("gmsh produced no tetrahedra (surface self-intersecting or too coarse?)");
  }
  orient_tets_positively(result);
  int offset = 0;
  for (std::size_t b = 0; b < boundaries.size(); ++b) {
    for (const auto& t : boundaries[b]->triangles) {
      // Holes face into the cavity, away from the material.
      result.surface_faces.push_back(b == 0
                                         ? Triangle{t[0] + offset, t[1] + offset, t[2] + offset}
                                         : Triangle{t[0] + offset, t[2] + offset, t[1] + offset});
    }
    offset += static_cast<int>(boundaries[b]->vertices.size());
  }
  progress.step();
  return result;
}

}  // namespace viscera::core
