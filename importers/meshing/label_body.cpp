#include "importers/meshing/label_body.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <future>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "importers/meshing/tet_boundary_surface.h"

namespace viscera::importers {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Until destroyed: cancels `side` as soon as `main` is cancelled (a user's Cancel reaches the
/// surface thread too), and both when `seconds` have passed (0: never).
class Deadline {
 public:
  Deadline(double seconds, core::Progress& main, core::Progress& side) {
    const bool limited = seconds > 0.0 && std::isfinite(seconds);
    const auto until = std::chrono::steady_clock::now() +
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(limited ? seconds : 0.0));
    watcher_ = std::thread([this, limited, until, &main, &side] {
      std::unique_lock lock(mutex_);
      while (!wake_.wait_for(lock, std::chrono::milliseconds(50), [this] { return finished_; })) {
        if (limited && std::chrono::steady_clock::now() >= until) {
          expired_.store(true);
          main.cancel();
          side.cancel();
          return;
        }
        if (main.cancelled()) side.cancel();
      }
    });
  }
  ~Deadline() {
    {
      std::lock_guard lock(mutex_);
      finished_ = true;
    }
    wake_.notify_all();
    if (watcher_.joinable()) watcher_.join();
  }
  Deadline(const Deadline&) = delete;
  Deadline& operator=(const Deadline&) = delete;

  bool expired() const { return expired_.load(); }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool finished_ = false;
  std::atomic<bool> expired_{false};
  std::thread watcher_;
};

/// `stage` with the budget spent as the reason, naming `what`.
core::ValidationError out_of_time(double budget, const std::string& stage,
                                  const std::string& what) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", budget);
  return core::ValidationError("meshing did not finish within its time budget of " +
                                   std::string(seconds) + " s (stopped during the " + stage +
                                   "); give a larger --time-limit or fewer --tets",
                               {what, "", ""});
}

}  // namespace

LabelBody mesh_label_body(const core::LabelMap& labels, const LabelBodyOptions& options,
                          const std::string& what, core::Progress& caller_progress) {
  // The budget cancels the Progress the work reports to: the caller's own, or one of this call
  // when the caller gave the shared silent one (which must never be cancelled).
  core::Progress own;
  core::Progress& progress = &caller_progress == &core::Progress::none() ? own : caller_progress;
  LabelBody result;
  const auto begin = std::chrono::steady_clock::now();
  // The bar follows Mesh_3; the surface thread reports to a Progress of its own, cancelled
  // when the tets end with an error, a cancellation or the time budget.
  core::Progress quiet;
  const Deadline deadline(options.time_limit_seconds, progress, quiet);
  std::string stage = "tetrahedra";
  try {
    const bool contour = options.visual_surface == VisualSurfaceSource::LabelContour;
    const auto make_surface = [&](core::Progress& surface_progress) {
      const auto start = std::chrono::steady_clock::now();
      LabelSurface surface =
          label_surface(labels, options.tets.label, options.surface, what, surface_progress);
      surface.seconds["total"] = seconds_since(start);
      return surface;
    };
    std::future<LabelSurface> surface;
    if (contour && options.concurrent_surface) {
      surface = std::async(std::launch::async, [&] { return make_surface(quiet); });
    } else if (contour) {
      stage = "visual surface";
      result.surface = make_surface(progress);
      stage = "tetrahedra";
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
    stage = "visual surface";
    if (contour) {
      if (surface.valid()) result.surface = surface.get();
      for (const auto& [step, seconds] : result.surface.seconds)
        result.seconds[step == "total" ? "surface" : "surface." + step] = seconds;
      stage = "embedding";
      start = std::chrono::steady_clock::now();
      progress.check_cancelled();
      result.embedding = core::embed_points(result.surface.mesh.vertices, result.body);
      result.seconds["embedding"] = seconds_since(start);
    } else {
      start = std::chrono::steady_clock::now();
      progress.check_cancelled();
      TetBoundarySurface boundary = tet_boundary_surface(result.body);
      result.surface.label = options.tets.label;
      result.surface.mesh = std::move(boundary.mesh);
      result.embedding = std::move(boundary.embedding);
      // Surface and embedding are one step here.
      result.seconds["surface"] = seconds_since(start);
      result.seconds["embedding"] = 0.0;
    }

    stage = "quality report";
    start = std::chrono::steady_clock::now();
    progress.check_cancelled();
    result.quality = core::tet_quality(result.body, options.quality);
    result.seconds["quality"] = seconds_since(start);
    result.seconds["total"] = seconds_since(begin);
  } catch (const core::CancelledError&) {
    if (deadline.expired()) throw out_of_time(options.time_limit_seconds, stage, what);
    throw;
  }
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
