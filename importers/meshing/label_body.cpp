#include "importers/meshing/label_body.h"

#include <algorithm>
#include <chrono>
#include <future>

namespace viscera::importers {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

LabelBody mesh_label_body(const core::LabelMap& labels, const LabelBodyOptions& options,
                          const std::string& what, core::Progress& progress) {
  LabelBody result;
  const auto begin = std::chrono::steady_clock::now();
  const auto make_surface = [&](core::Progress& surface_progress) {
    const auto start = std::chrono::steady_clock::now();
    LabelSurface surface =
        label_surface(labels, options.tets.label, options.surface, what, surface_progress);
    surface.seconds["total"] = seconds_since(start);
    return surface;
  };
  std::future<LabelSurface> surface;
  // The bar follows Mesh_3; the surface thread reports to a Progress of its own, cancelled
  // when the tets end with an error or a cancellation.
  core::Progress quiet;
  if (options.concurrent_surface) {
    surface = std::async(std::launch::async, [&] { return make_surface(quiet); });
  } else {
    result.surface = make_surface(progress);
  }
  auto start = std::chrono::steady_clock::now();
  try {
    result.body = mesh_label_map(labels, options.tets, what, progress, &result.criteria);
  } catch (...) {
    quiet.cancel();
    if (surface.valid()) surface.wait();
    throw;
  }
  result.seconds["tets"] = seconds_since(start);
  if (surface.valid()) result.surface = surface.get();
  for (const auto& [step, seconds] : result.surface.seconds)
    result.seconds[step == "total" ? "surface" : "surface." + step] = seconds;

  start = std::chrono::steady_clock::now();
  progress.check_cancelled();
  result.embedding = core::embed_points(result.surface.mesh.vertices, result.body);
  result.seconds["embedding"] = seconds_since(start);

  start = std::chrono::steady_clock::now();
  result.quality = core::tet_quality(result.body, options.quality);
  result.seconds["quality"] = seconds_since(start);
  result.seconds["total"] = seconds_since(begin);
  return result;
}

double embedding_error(const core::SurfaceMesh& surface, const core::SurfaceEmbedding& embedding,
                       const core::TetMesh& body) {
  const auto rebuilt = core::embedded_positions(embedding, body.tets, body.nodes);
  double worst = 0.0;
  for (std::size_t v = 0; v < rebuilt.size(); ++v)
    worst = std::max(worst, (rebuilt[v] - surface.vertices[v]).norm());
  return worst;
}

}  // namespace viscera::importers
