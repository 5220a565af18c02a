#pragma once
/// The segmentation the studio edits beside its document (issue 9 §4; seed 001 §3.3: organs
/// modelled from image volumes): a working image volume and its label map, changed by the same
/// library functions as `viscera segment` (core/segmentation/), and the organ object meshed
/// from one label by the pipeline of `viscera mesh tets` (importers::mesh_label_body). No
/// widgets: the panel and the tests call it alike. Lengths in m.

#include <array>
#include <cstdint>
#include <string>

#include "core/image/image_volume.h"
#include "core/progress.h"
#include "core/scenario/material.h"
#include "core/scenario/scene_object.h"
#include "importers/meshing/label_tet_mesher.h"

namespace viscera::studio {

/// A label map being built on an image volume. Every edit draws over the labels already there,
/// in the CLI's order of operations; it never changes the volume. An edit that throws leaves
/// the labels as they were (each computes its result before it changes them).
class Segmentation {
 public:
  /// Starts over on `volume` with an empty label map.
  void set_volume(core::ImageVolume volume);
  bool has_volume() const { return volume_.voxel_count() > 0; }
  const core::ImageVolume& volume() const { return volume_; }
  const core::LabelMap& labels() const { return labels_; }
  /// Replaces the label map (an opened label file); throws core::InputError naming `what` when
  /// its dims, spacing, origin or direction differ from the volume's.
  void set_labels(core::LabelMap labels, const std::string& what);
  /// Removes every label.
  void clear();

  /// Voxels of `label` become background, then those with lower ≤ value ≤ upper get `label`
  /// (core::threshold). Throws core::UsageError as core::threshold.
  void threshold(double lower, double upper, std::uint16_t label);
  /// The 6-connected region within `tolerance` of the value at world point `point` (m) gets
  /// `label` (core::grow_region from core::voxel_at); returns the seed voxel. Throws
  /// core::UsageError for a point outside the volume.
  std::array<int, 3> grow_at(const core::Vec3& point, double tolerance, std::uint16_t label);
  /// Morphological opening / closing with a ball of `radius` voxels
  /// (core/segmentation/morphology.h).
  void open(int radius);
  void close(int radius);
  /// Each label keeps only its largest 6-connected component.
  void keep_largest();

  /// Voxels holding `label`.
  std::size_t voxel_count(std::uint16_t label) const;
  /// Their volume, m³ (count × voxel volume).
  double label_volume(std::uint16_t label) const;

 private:
  void require_volume() const;

  core::ImageVolume volume_;
  core::LabelMap labels_;
};

/// How to mesh an organ from one label (the options of `viscera mesh tets` on a label map).
struct OrganMeshRequest {
  std::uint16_t label = 1;
  double cell_size = 0.0;          ///< m, largest tet circumradius; 0: from target_tets
  std::size_t target_tets = 5000;  ///< approximate tet count when cell_size is 0
  std::size_t triangles = 4000;    ///< visual surface triangle budget
  std::string name;                ///< object name; empty: the label's name or "Organ"
  std::string material = "liver";  ///< shipped material id when the scenario has none of that id
};

/// Passes of Mesh_3 organ_tet_criteria runs at most, and the relative tet-count error it stops at.
inline constexpr int kOrganMeshPasses = 5;
inline constexpr double kOrganMeshTolerance = 0.1;

/// The Mesh_3 criteria that give about `request.target_tets` tets for the label (issue 23 §5:
/// the count within ±20 %) when `request.cell_size` is 0: the cell size from the labelled
/// volume (importers::resolve_tet_criteria), then up to kOrganMeshPasses runs of
/// importers::mesh_label_map, each rescaling the cell size by the cube root of the count's
/// ratio to the target, until it is within kOrganMeshTolerance; the closest run's criteria are
/// returned and its count stored in `tets_found`. Facet size follows the cell size, facet
/// distance a tenth of it (at least half a voxel), so the boundary does not set the count. With a
/// cell size given, the request's criteria as they are. Throws as mesh_label_map.
importers::LabelTetMeshingOptions organ_tet_criteria(const core::LabelMap& labels,
                                                     const OrganMeshRequest& request,
                                                     const std::string& what,
                                                     core::Progress& progress,
                                                     std::size_t* tets_found = nullptr);

/// The organ object `id` meshed from `request.label` of `labels`: the closed visual surface
/// (importers::label_surface), the tets filling the label (CGAL Mesh_3) with lumped masses from
/// `material.density`, nothing fixed, and the surface embedded in the tets — ready for the
/// simulator. The tets follow organ_tet_criteria; `progress` gets one stage whose bar moves
/// through every Mesh_3 pass and the body. Throws core::InputError for a label without voxels,
/// core::ValidationError when meshing fails, core::CancelledError through `progress`. Runs on any
/// thread.
core::SceneObject build_organ_object(const core::LabelMap& labels, const OrganMeshRequest& request,
                                     const std::string& id, const core::Material& material,
                                     core::Progress& progress = core::Progress::none());

}  // namespace viscera::studio
