#include "importers/meshing/label_tet_mesher.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "core/error.h"
#include "importers/meshing/label_crop.h"
#include "importers/meshing/label_mesh_3.h"

namespace viscera::importers {
namespace {

constexpr double kMillimetresPerMetre = 1000.0;
/// Volume per tet over cell_size³ for Mesh_3 at radius-edge ratio 3 with exudation and the
/// default facet criteria: measured 0.197 on CGAL's liver at label 255 (issue 20: 144,661 tets
/// of 11.1 mm³ at a 3.83 mm cell size) and 0.21 on the liver thresholded at 128 and opened; a
/// little above both, so the count lands at or just above the target rather than below it.
constexpr double kVolumePerTetOverCellSizeCubed = 0.22;
/// The automatic facet distance: facet size over this (a sag of a sixth of the facet).
constexpr double kFacetSizeOverDistance = 6.0;
/// The automatic cell size never resolves less than this many voxel spacings.
constexpr double kMinimumCellSizeInSpacings = 1.5;

void check_options(const LabelTetMeshingOptions& o) {
  const auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!non_negative(o.cell_size) || !non_negative(o.facet_size) ||
      !non_negative(o.facet_distance)) {
    throw core::UsageError("cell size, facet size and facet distance must be finite and ≥ 0");
  }
  if (!(o.exude_sliver_bound_degrees >= 0.0 && o.exude_sliver_bound_degrees < 90.0)) {
    throw core::UsageError("the exudation sliver bound must be in [0°, 90°)");
  }
  if (!(o.cell_radius_edge_ratio >= 2.0)) {
    throw core::UsageError("the cell radius-edge ratio bound must be at least 2");
  }
  if (!(o.facet_angle_degrees > 0.0 && o.facet_angle_degrees <= 30.0)) {
    throw core::UsageError("the facet angle bound must be in (0°, 30°] for Mesh_3 to terminate");
  }
  for (const auto& [label, size] : o.label_cell_size) {
    if (!(std::isfinite(size) && size > 0.0)) {
      throw core::UsageError("the cell size of label " + std::to_string(label) +
                             " must be positive");
    }
  }
  if (o.cell_size == 0.0 && o.target_tets == 0) {
    throw core::UsageError("give a cell size or a target tet count");
  }
}

ResolvedTetCriteria resolve(const core::LabelMap& labels, const LabelTetMeshingOptions& o,
                            std::size_t labelled_voxels) {
  const core::Vec3& spacing = labels.image.spacing;
  ResolvedTetCriteria c;
  c.cell_size = o.cell_size;
  if (c.cell_size == 0.0) {
    const double volume = static_cast<double>(labelled_voxels) * spacing.prod();
    c.cell_size = std::max(
        std::cbrt(volume / (kVolumePerTetOverCellSizeCubed * static_cast<double>(o.target_tets))),
        kMinimumCellSizeInSpacings * spacing.maxCoeff());
  }
  c.facet_size = o.facet_size > 0.0 ? o.facet_size : c.cell_size;
  c.facet_distance = o.facet_distance > 0.0
                         ? o.facet_distance
                         : std::clamp(c.facet_size / kFacetSizeOverDistance,
                                      0.5 * spacing.minCoeff(), spacing.minCoeff());
  return c;
}

}  // namespace

ResolvedTetCriteria resolve_tet_criteria(const core::LabelMap& labels,
                                         const LabelTetMeshingOptions& options,
                                         const std::string& what) {
  check_options(options);
  const LabelCrop crop = crop_labels(labels, options.label, 1, what);
  return resolve(labels, options, crop.labelled_voxels);
}

core::TetMesh mesh_label_map(const core::LabelMap& labels, const LabelTetMeshingOptions& options,
                             const std::string& what, core::Progress& progress,
                             ResolvedTetCriteria* used) {
  check_options(options);
  if (!(labels.image.spacing.array() > 0.0).all() || !labels.image.spacing.allFinite()) {
    throw core::InputError("the label map's voxel spacing is not positive", {what, "", ""});
  }
  progress.begin_stage("tetrahedra (CGAL Mesh_3)", 3);
  // One voxel of background around the labels: Mesh_3's domain is the image's box, and the
  // boundary of a label touching the map's border must lie inside it.
  const LabelCrop crop = crop_labels(labels, options.label, 1, what);
  const ResolvedTetCriteria criteria = resolve(labels, options, crop.labelled_voxels);
  if (used != nullptr) *used = criteria;
  progress.step();

  detail::Mesh3Input input;
  input.crop = &crop;
  input.spacing_mm = labels.image.spacing * kMillimetresPerMetre;
  input.cell_size_mm = criteria.cell_size * kMillimetresPerMetre;
  for (const auto& [label, size] : options.label_cell_size)
    input.label_cell_size_mm[label] = size * kMillimetresPerMetre;
  input.cell_radius_edge_ratio = options.cell_radius_edge_ratio;
  input.facet_angle_degrees = options.facet_angle_degrees;
  input.facet_size_mm = criteria.facet_size * kMillimetresPerMetre;
  input.facet_distance_mm = criteria.facet_distance * kMillimetresPerMetre;
  input.exude = options.exude;
  input.exude_sliver_bound_degrees = options.exude_sliver_bound_degrees;
  input.threads = options.threads;
  input.seed = options.seed;
  // Cancel reaches Mesh_3 through its stop flag, which a watcher sets from the progress.
  std::atomic<bool> stop{false};
  input.stop = &stop;
  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!done.load()) {
      if (progress.cancelled()) stop.store(true);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
  detail::Mesh3Output output;
  try {
    output = options.threads > 1 ? detail::run_mesh_3_parallel(input)
                                 : detail::run_mesh_3_sequential(input);
  } catch (...) {
    done.store(true);
    watcher.join();
    throw;
  }
  done.store(true);
  watcher.join();
  progress.step();
  if (output.tets.empty()) {
    throw core::ValidationError(
        "CGAL Mesh_3 produced no tetrahedra: the labelled region is thinner than the criteria "
        "resolve; lower the cell size",
        {what, "", ""});
  }

  core::TetMesh body;
  const core::Vec3 origin = crop_origin(labels, crop);
  const core::Mat3& direction = labels.image.direction;
  body.nodes.reserve(output.nodes_mm.size());
  for (const auto& p : output.nodes_mm)
    body.nodes.push_back(origin + direction * (p / kMillimetresPerMetre));
  body.tets = output.tets;
  body.tet_labels = output.labels;
  // A mirroring direction matrix turns every tet inside out.
  if (direction.determinant() < 0.0) {
    for (auto& tet : body.tets)
      std::swap(tet[2], tet[3]);
  }
  body.surface_faces = core::boundary_faces(body.tets);
  progress.step();
  return body;
}

}  // namespace viscera::importers
