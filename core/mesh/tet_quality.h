#pragma once
/// Shape quality of tetrahedral meshes: the report every simulation body gets before it goes
/// into a package (issue 3 §4), and the check that a variant's body is fit for the solver.
///
/// Measures per tet (Shewchuk, "What is a good linear finite element?", 2002; verdict's
/// definitions as in VTK's vtkMeshQuality):
/// - dihedral angles: the six angles between face pairs, in degrees (70.53° for a regular tet);
/// - radius-edge ratio: circumradius / shortest edge (√6/4 ≈ 0.612 for a regular tet; Mesh_3's
///   cell_radius_edge_ratio bounds it);
/// - aspect ratio: longest edge / (2√6 · inradius), 1 for a regular tet, growing without bound as
///   the tet flattens (verdict's tet aspect ratio).
/// A tet is inverted when its signed volume is not positive, a sliver when it is positive but
/// its smallest dihedral angle is below TetQualityOptions::sliver_angle_degrees.

#include <array>
#include <cstddef>
#include <nlohmann/json_fwd.hpp>

#include "core/mesh/tet_mesh.h"

namespace viscera::core {

/// Shape measures of one tetrahedron.
struct TetShape {
  double signed_volume = 0.0;  ///< m³
  double min_dihedral_degrees = 0.0;
  double max_dihedral_degrees = 0.0;
  double radius_edge_ratio = 0.0;  ///< infinite for a flat tet
  double aspect_ratio = 0.0;       ///< infinite for a flat tet
};

/// Thresholds of the report.
struct TetQualityOptions {
  /// A positive tet whose smallest dihedral angle is below this, in degrees, is a sliver.
  double sliver_angle_degrees = 5.0;
};

/// Summary over a mesh. The shape statistics are over the positive tets only (an inverted or
/// flat tet has no meaningful circumradius); they are NaN when there are none.
struct TetQualityReport {
  std::size_t tets = 0;
  std::size_t nodes = 0;
  std::size_t inverted = 0;  ///< signed volume ≤ 0
  std::size_t slivers = 0;   ///< positive, smallest dihedral angle below the threshold
  double sliver_angle_degrees = 5.0;
  double total_volume = 0.0;  ///< sum of signed volumes, m³
  double min_volume = 0.0;    ///< smallest signed volume, m³
  double min_dihedral_degrees = 0.0;
  double max_dihedral_degrees = 0.0;
  double min_radius_edge_ratio = 0.0;
  double mean_radius_edge_ratio = 0.0;
  double max_radius_edge_ratio = 0.0;
  double mean_aspect_ratio = 0.0;
  double max_aspect_ratio = 0.0;
  int worst_tet = -1;  ///< index of the tet with the smallest dihedral angle, or -1
  /// Counts of positive tets by smallest dihedral angle: [0,5), [5,10), [10,20), [20,30), ≥30°.
  std::array<std::size_t, 5> min_dihedral_histogram{};

  /// True when no tet is inverted.
  bool valid() const { return inverted == 0; }
};

/// Shape of the tet (a, b, c, d), positions in m.
TetShape tet_shape(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Quality report of every tet of `mesh`. Node indices must be valid (core::check_tet_mesh).
TetQualityReport tet_quality(const TetMesh& mesh, const TetQualityOptions& options = {});

/// JSON form of the report: snake_case keys as the struct, NaN statistics as null.
void to_json(nlohmann::json& json, const TetQualityReport& report);

}  // namespace viscera::core
