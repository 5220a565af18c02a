#include "templates/vessels/perfusion_domain.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::templates {

core::Vec3 PerfusionDomain::random_point(core::Rng& rng) const {
  const core::BoundingBox box = bounds();
  for (int attempt = 0; attempt < 100000; ++attempt) {
    const core::Vec3 p(rng.uniform(box.min.x(), box.max.x()), rng.uniform(box.min.y(), box.max.y()),
                       rng.uniform(box.min.z(), box.max.z()));
    if (contains(p)) return p;
  }
  throw core::InputError("the domain is too thin to draw points from");
}

core::Vec3 PerfusionDomain::default_inlet() const {
  const core::BoundingBox box = bounds();
  const core::Vec3 target(box.center().x(), box.center().y(), box.min.z());
  core::Rng rng(0x1e7);
  core::Vec3 best = random_point(rng);
  for (int i = 0; i < 4000; ++i) {
    const core::Vec3 p = random_point(rng);
    if ((p - target).squaredNorm() < (best - target).squaredNorm()) best = p;
  }
  return best;
}

bool PerfusionDomain::contains_segment(const core::Vec3& a, const core::Vec3& b) const {
  const double step = 0.5 * resolution();
  const int samples = std::max(2, static_cast<int>(std::ceil((b - a).norm() / step)) + 1);
  for (int i = 0; i < samples; ++i) {
    if (!contains(a + (b - a) * (static_cast<double>(i) / (samples - 1)))) return false;
  }
  return true;
}

/// Triangles binned by their projection onto the plane orthogonal to one axis.
struct SurfaceMeshDomain::AxisGrid {
  int axis = 0, u = 1, v = 2;
  double u0 = 0, v0 = 0, cell = 1;
  int nu = 1, nv = 1;
  std::vector<std::vector<int>> bins;
};

SurfaceMeshDomain::SurfaceMeshDomain(core::SurfaceMesh mesh, const std::string& what)
    : mesh_(std::move(mesh)) {
  if (mesh_.triangles.empty())
    throw core::InputError("the domain mesh has no triangles", {what, "", ""});
  core::check_surface_mesh(mesh_, what);
  box_ = core::bounds(mesh_);
  volume_ = std::abs(core::enclosed_volume(mesh_));
  const double extent = box_.size().maxCoeff();
  if (!(volume_ > 1e-12 * extent * extent * extent) || !(extent > 0.0)) {
    throw core::InputError("the domain mesh encloses no volume", {what, "", ""});
  }
  double edge = 0.0;
  for (const auto& t : mesh_.triangles)
    edge += (mesh_.vertices[t[1]] - mesh_.vertices[t[0]]).norm();
  edge /= static_cast<double>(mesh_.triangles.size());
  resolution_ = std::max(edge, 1e-3 * extent);
  const int per_side = std::clamp(
      static_cast<int>(std::sqrt(static_cast<double>(mesh_.triangles.size()) / 2.0)), 1, 512);
  for (int axis = 0; axis < 3; ++axis) {
    auto grid = std::make_unique<AxisGrid>();
    grid->axis = axis;
    grid->u = (axis + 1) % 3;
    grid->v = (axis + 2) % 3;
    grid->u0 = box_.min[grid->u];
    grid->v0 = box_.min[grid->v];
    grid->cell = std::max(box_.size()[grid->u], box_.size()[grid->v]) / per_side * 1.0001 + 1e-12;
    grid->nu = static_cast<int>(box_.size()[grid->u] / grid->cell) + 1;
    grid->nv = static_cast<int>(box_.size()[grid->v] / grid->cell) + 1;
    grid->bins.resize(static_cast<std::size_t>(grid->nu) * grid->nv);
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      double lo_u = INFINITY, hi_u = -INFINITY, lo_v = INFINITY, hi_v = -INFINITY;
      for (const int k : mesh_.triangles[t]) {
        lo_u = std::min(lo_u, mesh_.vertices[k][grid->u]);
        hi_u = std::max(hi_u, mesh_.vertices[k][grid->u]);
        lo_v = std::min(lo_v, mesh_.vertices[k][grid->v]);
        hi_v = std::max(hi_v, mesh_.vertices[k][grid->v]);
      }
      const int iu0 = std::clamp(static_cast<int>((lo_u - grid->u0) / grid->cell), 0, grid->nu - 1);
      const int iu1 = std::clamp(static_cast<int>((hi_u - grid->u0) / grid->cell), 0, grid->nu - 1);
      const int iv0 = std::clamp(static_cast<int>((lo_v - grid->v0) / grid->cell), 0, grid->nv - 1);
      const int iv1 = std::clamp(static_cast<int>((hi_v - grid->v0) / grid->cell), 0, grid->nv - 1);
      for (int iu = iu0; iu <= iu1; ++iu)
        for (int iv = iv0; iv <= iv1; ++iv)
          grid->bins[static_cast<std::size_t>(iu) * grid->nv + iv].push_back(static_cast<int>(t));
    }
    grids_.push_back(std::move(grid));
  }
}

SurfaceMeshDomain::~SurfaceMeshDomain() = default;

int SurfaceMeshDomain::crossings(const core::Vec3& p, int axis) const {
  const AxisGrid& g = *grids_[axis];
  const int iu = static_cast<int>(std::floor((p[g.u] - g.u0) / g.cell));
  const int iv = static_cast<int>(std::floor((p[g.v] - g.v0) / g.cell));
  if (iu < 0 || iv < 0 || iu >= g.nu || iv >= g.nv) return 0;
  int count = 0;
  for (const int t : g.bins[static_cast<std::size_t>(iu) * g.nv + iv]) {
    const auto& tri = mesh_.triangles[t];
    const core::Vec3& a = mesh_.vertices[tri[0]];
    const core::Vec3& b = mesh_.vertices[tri[1]];
    const core::Vec3& c = mesh_.vertices[tri[2]];
    // 2D point-in-triangle in the (u, v) plane with signed areas.
    const auto cross = [&](const core::Vec3& s, const core::Vec3& e) {
      return (e[g.u] - s[g.u]) * (p[g.v] - s[g.v]) - (e[g.v] - s[g.v]) * (p[g.u] - s[g.u]);
    };
    const double w0 = cross(b, c), w1 = cross(c, a), w2 = cross(a, b);
    const bool positive = w0 >= 0 && w1 >= 0 && w2 >= 0 && (w0 > 0 || w1 > 0 || w2 > 0);
    const bool negative = w0 <= 0 && w1 <= 0 && w2 <= 0 && (w0 < 0 || w1 < 0 || w2 < 0);
    if (!positive && !negative) continue;
    const double sum = w0 + w1 + w2;
    const double hit = (w0 * a[g.axis] + w1 * b[g.axis] + w2 * c[g.axis]) / sum;
    if (hit > p[g.axis]) ++count;
  }
  return count;
}

bool SurfaceMeshDomain::contains(const core::Vec3& point) const {
  if ((point.array() < box_.min.array()).any() || (point.array() > box_.max.array()).any())
    return false;
  // A tiny shift by incommensurate fractions of the extent: symmetric meshes (an icosphere has
  // vertices and edges on the axes) would otherwise put axis rays exactly through shared edges,
  // where parity counting fails. Points within 10⁻⁷ of the wall may go either way.
  const core::Vec3 p =
      point + box_.size().maxCoeff() * core::Vec3(1.2345679e-7, 2.7182818e-7, 1.4142136e-7);
  int votes = 0;
  for (int axis = 0; axis < 3; ++axis)
    votes += crossings(p, axis) % 2;
  return votes >= 2;
}

LabelMapDomain::LabelMapDomain(core::LabelMap labels, int label, const std::string& what)
    : labels_(std::move(labels)), label_(label) {
  const auto& image = labels_.image;
  if (image.scalar_type != core::ScalarType::UInt16 ||
      image.voxels.size() != image.voxel_count() * 2) {
    throw core::InputError("the label map must hold one unsigned 16-bit label per voxel",
                           {what, "", ""});
  }
  for (std::size_t i = 0; i < image.voxel_count(); ++i) {
    if (inside_voxel(i)) inside_.push_back(i);
  }
  if (inside_.empty()) {
    throw core::InputError(label ? "no voxel carries label " + std::to_string(label)
                                 : "the label map has no labelled voxel",
                           {what, "", ""});
  }
  const core::Mat3 index_to_world = image.direction * image.spacing.asDiagonal();
  world_to_index_ = index_to_world.inverse();
  volume_ = static_cast<double>(inside_.size()) * std::abs(index_to_world.determinant());
  for (const std::size_t linear : inside_) {
    const int i = static_cast<int>(linear % image.dims[0]);
    const int j = static_cast<int>((linear / image.dims[0]) % image.dims[1]);
    const int k =
        static_cast<int>(linear / (static_cast<std::size_t>(image.dims[0]) * image.dims[1]));
    for (int corner = 0; corner < 8; ++corner) {
      box_.add(image.index_to_world(core::Vec3(i + ((corner & 1) ? 0.5 : -0.5),
                                               j + ((corner & 2) ? 0.5 : -0.5),
                                               k + ((corner & 4) ? 0.5 : -0.5))));
    }
  }
}

bool LabelMapDomain::inside_voxel(std::size_t linear) const {
  const int value = labels_.label(linear);
  return label_ == 0 ? value != 0 : value == label_;
}

bool LabelMapDomain::contains(const core::Vec3& p) const {
  const core::Vec3 ijk = world_to_index_ * (p - labels_.image.origin);
  const auto& dims = labels_.image.dims;
  int index[3];
  for (int a = 0; a < 3; ++a) {
    index[a] = static_cast<int>(std::lround(ijk[a]));
    if (index[a] < 0 || index[a] >= dims[a]) return false;
  }
  return inside_voxel(labels_.image.linear_index(index[0], index[1], index[2]));
}

core::Vec3 LabelMapDomain::random_point(core::Rng& rng) const {
  // A random domain voxel, then a uniform point in it: exact and fast for thin organs.
  const std::size_t linear = inside_[static_cast<std::size_t>(
      rng.uniform_int(0, static_cast<std::int64_t>(inside_.size()) - 1))];
  const auto& dims = labels_.image.dims;
  const double i = static_cast<double>(linear % dims[0]);
  const double j = static_cast<double>((linear / dims[0]) % dims[1]);
  const double k = static_cast<double>(linear / (static_cast<std::size_t>(dims[0]) * dims[1]));
  return labels_.image.index_to_world(core::Vec3(
      i + rng.uniform(-0.5, 0.5), j + rng.uniform(-0.5, 0.5), k + rng.uniform(-0.5, 0.5)));
}

}  // namespace viscera::templates
