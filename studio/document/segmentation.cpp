#include "studio/document/segmentation.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/error.h"
#include "core/mesh/tet_mesh.h"
#include "core/segmentation/label_operations.h"
#include "core/segmentation/morphology.h"
#include "core/segmentation/region_growing.h"
#include "core/segmentation/threshold.h"
#include "importers/meshing/label_body.h"

namespace viscera::studio {

void Segmentation::set_volume(core::ImageVolume volume) {
  volume_ = std::move(volume);
  labels_ = core::empty_label_map(volume_);
}

void Segmentation::set_labels(core::LabelMap labels, const std::string& what) {
  require_volume();
  const auto& a = labels.image;
  const auto& b = volume_;
  if (a.dims != b.dims || !a.spacing.isApprox(b.spacing, 1e-9) ||
      !a.origin.isApprox(b.origin, 1e-9) || !a.direction.isApprox(b.direction, 1e-9)) {
    throw core::InputError("the label map's grid (" + std::to_string(a.dims[0]) + " × " +
                               std::to_string(a.dims[1]) + " × " + std::to_string(a.dims[2]) +
                               " voxels) does not match the image volume's (" +
                               std::to_string(b.dims[0]) + " × " + std::to_string(b.dims[1]) +
                               " × " + std::to_string(b.dims[2]) + ")",
                           {what, "", ""});
  }
  labels_ = std::move(labels);
}

void Segmentation::clear() {
  labels_ = core::empty_label_map(volume_);
}

void Segmentation::require_volume() const {
  if (!has_volume()) throw core::UsageError("open an image volume before segmenting");
}

void Segmentation::threshold(double lower, double upper, std::uint16_t label) {
  require_volume();
  const core::LabelMap band = core::threshold(volume_, lower, upper, label);
  for (std::size_t v = 0; v < labels_.image.voxel_count(); ++v) {
    if (band.label(v) != 0) {
      labels_.set_label(v, label);
    } else if (labels_.label(v) == label) {
      labels_.set_label(v, 0);
    }
  }
}

std::array<int, 3> Segmentation::grow_at(const core::Vec3& point, double tolerance,
                                         std::uint16_t label) {
  require_volume();
  const std::array<int, 3> seed = core::voxel_at(volume_, point);
  const core::LabelMap grown = core::grow_region(volume_, seed, tolerance, label);
  for (std::size_t v = 0; v < labels_.image.voxel_count(); ++v)
    if (grown.label(v) != 0) labels_.set_label(v, label);
  return seed;
}

void Segmentation::open(int radius) {
  require_volume();
  labels_ = core::open_labels(labels_, radius);
}

void Segmentation::close(int radius) {
  require_volume();
  labels_ = core::close_labels(labels_, radius);
}

void Segmentation::keep_largest() {
  require_volume();
  labels_ = core::keep_largest_component(labels_);
}

std::size_t Segmentation::voxel_count(std::uint16_t label) const {
  std::size_t count = 0;
  for (std::size_t v = 0; v < labels_.image.voxel_count(); ++v)
    count += labels_.label(v) == label ? 1 : 0;
  return count;
}

double Segmentation::label_volume(std::uint16_t label) const {
  return static_cast<double>(voxel_count(label)) * volume_.spacing.prod();
}

namespace {

/// Facet distance = cell size / this (at least half a voxel): the surface stays within it of
/// the label's border, and the boundary does not set the tet count.
constexpr double kFacetDistanceDivisor = 10.0;

/// One overall stage of `parent` (kUnits units) that child work reports into, each child's
/// fractions mapped onto a span of it: the bar moves through every pass.
class OverallProgress {
 public:
  static constexpr std::int64_t kUnits = 1000;

  OverallProgress(core::Progress& parent, const std::string& stage) : parent_(parent) {
    parent_.begin_stage(stage, kUnits);
  }
  /// Moves the bar to `fraction` of the whole (never back); throws CancelledError.
  void advance_to(double fraction) {
    const auto units =
        static_cast<std::int64_t>(std::lround(kUnits * std::clamp(fraction, 0.0, 1.0)));
    if (units > reported_) {
      parent_.step(units - reported_);
      reported_ = units;
    }
    parent_.check_cancelled();
  }

 private:
  core::Progress& parent_;
  std::int64_t reported_ = 0;
};

}  // namespace

importers::LabelTetMeshingOptions organ_tet_criteria(const core::LabelMap& labels,
                                                     const OrganMeshRequest& request,
                                                     const std::string& what,
                                                     core::Progress& progress,
                                                     std::size_t* tets_found) {
  importers::LabelTetMeshingOptions options;
  options.label = request.label;
  options.cell_size = request.cell_size;
  options.target_tets = request.target_tets;
  if (request.cell_size > 0.0 || request.target_tets == 0) return options;
  const importers::ResolvedTetCriteria first =
      importers::resolve_tet_criteria(labels, options, what);
  const double target = static_cast<double>(request.target_tets);
  double cell = first.cell_size;
  double best_cell = cell;
  double best_error = -1.0;
  for (int pass = 0; pass < kOrganMeshPasses; ++pass) {
    options.cell_size = cell;
    options.facet_size = cell;
    options.facet_distance = std::max(first.facet_distance, cell / kFacetDistanceDivisor);
    const std::size_t count =
        importers::mesh_label_map(labels, options, what, progress).tets.size();
    const double error = std::abs(static_cast<double>(count) / target - 1.0);
    if (best_error < 0.0 || error < best_error) {
      best_error = error;
      best_cell = cell;
      if (tets_found != nullptr) *tets_found = count;
    }
    if (error <= kOrganMeshTolerance) break;
    // The count goes as the inverse cube of the cell size; damp the step against overshoot.
    const double ratio =
        std::clamp(static_cast<double>(std::max<std::size_t>(count, 1)) / target, 0.05, 20.0);
    cell *= std::pow(ratio, 0.9 / 3.0);
  }
  options.cell_size = best_cell;
  options.facet_size = best_cell;
  options.facet_distance = std::max(first.facet_distance, best_cell / kFacetDistanceDivisor);
  return options;
}

core::SceneObject build_organ_object(const core::LabelMap& labels, const OrganMeshRequest& request,
                                     const std::string& id, const core::Material& material,
                                     core::Progress& progress) {
  if (request.label == 0) throw core::UsageError("label 0 is background, not an organ");
  const std::string what = "label " + std::to_string(request.label);
  OverallProgress overall(progress, "meshing " + what);
  // The passes that find the cell size take the first 60 % of the bar, the body the rest;
  // each reports its own stages through a child mapped onto its span.
  double from = 0.0, to = 0.6;
  core::Progress* child_pointer = nullptr;
  core::Progress child([&](double fraction, const std::string&) {
    if (progress.cancelled() && child_pointer != nullptr) child_pointer->cancel();
    overall.advance_to(from + fraction * (to - from));
  });
  child_pointer = &child;
  importers::LabelBodyOptions options;
  options.surface.target_triangles = request.triangles;
  options.tets = organ_tet_criteria(labels, request, what, child);
  overall.advance_to(0.6);
  from = 0.6;
  to = 1.0;
  importers::LabelBody made = importers::mesh_label_body(labels, options, what, child);
  overall.advance_to(1.0);

  core::SceneObject object;
  object.id = id;
  const auto named = labels.names.find(request.label);
  object.name = !request.name.empty()                                   ? request.name
                : named != labels.names.end() && !named->second.empty() ? named->second
                                                                        : "Organ";
  object.role = core::ObjectRole::Organ;
  object.material = material.id;
  object.surface = std::move(made.surface.mesh);
  object.body = std::move(made.body);
  object.body.node_mass = core::lumped_node_masses(object.body, material.density);
  object.body.fixed.assign(object.body.nodes.size(), 0);
  object.embedding = std::move(made.embedding);
  object.body_kind = core::BodyKind::TetMesh;
  return object;
}

}  // namespace viscera::studio
