#pragma once
/// Branching flexible pipes (seed 001 §3.3 "flexible pipe modelling"; §5.1.1: vessel trees "using
/// spline curves for interconnected pipes"): a root pipe and child pipes that leave a parent
/// at a point of its centre line. The branches are swept as tubes (pipe_primitive.h) and joined
/// into one watertight surface whose junctions are smooth fillets (pipe_junction.h). The basis
/// for vessels, fallopian tubes, urethra and intestine. Positions and radii in m.

#include <string>
#include <utility>
#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/primitives/pipe_primitive.h"
#include "core/progress.h"

namespace viscera::core {

/// One branch. A child's centre line starts at its attach point on the parent (derived, not a
/// control point) and continues through its own points.
struct PipeBranch {
  std::vector<Vec3> points;  ///< own centre-line control points, m (root ≥ 2, child ≥ 1)
  std::vector<double>
      radii;        ///< m, one per point; a child's first radius is also its radius at the parent
  int parent = -1;  ///< an earlier branch, or −1 for the root (branch 0 only)
  double attach = 1.0;  ///< where on the parent, as a fraction of its centre-line length

  bool operator==(const PipeBranch&) const = default;
};

/// A tree of pipes and how it is tessellated.
struct PipeNetwork {
  std::vector<PipeBranch> branches;
  PipeCap start_cap = PipeCap::Flat;  ///< the root's start
  PipeCap end_cap = PipeCap::Flat;    ///< every branch's far end
  int ring_segments = 32;             ///< vertices around each cross-section
  double axial_spacing = 0.0;         ///< m between cross-sections; 0 = ring edge length
  double blend = 0.6;  ///< junction fillet half-width as a fraction of the child's radius

  bool operator==(const PipeNetwork&) const = default;
};

/// A single root pipe through `points` with one radius.
PipeNetwork make_pipe_network(const std::vector<Vec3>& points, const std::vector<double>& radii);

/// Throws UsageError naming `what` and the branch for a parent that is not earlier, an attach
/// outside [0, 1], too few points, missing radii, or bad tessellation settings.
void check_pipe_network(const PipeNetwork& network, const std::string& what);

/// The point on branch b's parent where b starts (b > 0), in m.
Vec3 attach_point(const PipeNetwork& network, int branch);

/// Branch b as a single pipe: a child's centre line is its attach point followed by its points.
PipePrimitive branch_pipe(const PipeNetwork& network, int branch);

/// All control points in order: branch 0's points, then branch 1's, … (attach points excluded).
std::vector<Vec3> network_control_points(const PipeNetwork& network);
/// (branch, point) of a global control-point index; throws UsageError when out of range.
std::pair<int, int> locate_control_point(const PipeNetwork& network, int index);

/// The surface of the network: one swept tube when it has one branch, otherwise the union of
/// all tubes with smooth junctions. Watertight and outward when the caps are closed. Vertex
/// attribute "branch" holds the nearest branch of each vertex. Throws UsageError for bad
/// input, InputError when a tube folds onto itself (radius above its bend radius) or the
/// junctions cannot be joined; CancelledError through `progress`.
SurfaceMesh tessellate_pipe_network(const PipeNetwork& network,
                                    Progress& progress = Progress::none());

}  // namespace viscera::core
