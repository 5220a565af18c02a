#include "studio/document/segmentation.h"

#include <cctype>

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

core::SceneObject build_organ_object(const core::LabelMap& labels, const OrganMeshRequest& request,
                                     const std::string& id, const core::Material& material,
                                     core::Progress& progress) {
  if (request.label == 0) throw core::UsageError("label 0 is background, not an organ");
  importers::LabelBodyOptions options;
  options.tets.label = request.label;
  options.tets.cell_size = request.cell_size;
  options.tets.target_tets = request.target_tets;
  options.surface.target_triangles = request.triangles;
  const std::string what = "label " + std::to_string(request.label);
  importers::LabelBody made = importers::mesh_label_body(labels, options, what, progress);

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
