#pragma once
/// The organ a vessel tree perfuses: a closed surface mesh or the voxels of a label map.

#include <memory>
#include <vector>

#include "core/image/image_volume.h"
#include "core/math_types.h"
#include "core/mesh/surface_mesh.h"
#include "core/random.h"

namespace viscera::templates {

/// A region of space, in m.
class PerfusionDomain {
 public:
  virtual ~PerfusionDomain() = default;

  /// True when p lies inside.
  virtual bool contains(const core::Vec3& p) const = 0;
  virtual core::BoundingBox bounds() const = 0;
  /// Volume in m³.
  virtual double volume() const = 0;
  /// A point drawn uniformly from the domain.
  virtual core::Vec3 random_point(core::Rng& rng) const;
  /// Where the feeding artery enters by default: the inside point closest to the middle of the
  /// bounding box's bottom face (−z), as the uterine arteries reach the uterus from below.
  virtual core::Vec3 default_inlet() const;
  /// Length below which containment checks along a segment cannot resolve the domain.
  virtual double resolution() const = 0;

  /// True when points every resolution()/2 along a→b all lie inside.
  bool contains_segment(const core::Vec3& a, const core::Vec3& b) const;
};

/// The inside of a closed triangle surface, by the parity of ray crossings along three axes
/// (majority vote, so a ray grazing an edge cannot flip the answer), accelerated with grids of
/// the triangles' projections.
class SurfaceMeshDomain final : public PerfusionDomain {
 public:
  /// Throws core::InputError naming `what` when the mesh has no triangles or encloses no volume.
  SurfaceMeshDomain(core::SurfaceMesh mesh, const std::string& what = "domain");
  ~SurfaceMeshDomain() override;

  bool contains(const core::Vec3& p) const override;
  core::BoundingBox bounds() const override { return box_; }
  double volume() const override { return volume_; }
  double resolution() const override { return resolution_; }

 private:
  struct AxisGrid;
  int crossings(const core::Vec3& p, int axis) const;

  core::SurfaceMesh mesh_;
  core::BoundingBox box_;
  double volume_ = 0.0;
  double resolution_ = 0.0;
  std::vector<std::unique_ptr<AxisGrid>> grids_;  ///< one per ray axis
};

/// The voxels of a label map carrying `label` (0 = any non-zero label).
class LabelMapDomain final : public PerfusionDomain {
 public:
  /// Throws core::InputError naming `what` when no voxel carries the label.
  LabelMapDomain(core::LabelMap labels, int label = 0, const std::string& what = "domain");

  bool contains(const core::Vec3& p) const override;
  core::BoundingBox bounds() const override { return box_; }
  double volume() const override { return volume_; }
  core::Vec3 random_point(core::Rng& rng) const override;
  double resolution() const override { return labels_.image.spacing.minCoeff(); }

 private:
  bool inside_voxel(std::size_t linear) const;

  core::LabelMap labels_;
  int label_ = 0;
  std::vector<std::size_t> inside_;  ///< linear indices of the domain's voxels
  core::Mat3 world_to_index_;        ///< (direction · diag(spacing))⁻¹
  core::BoundingBox box_;
  double volume_ = 0.0;
};

}  // namespace viscera::templates
