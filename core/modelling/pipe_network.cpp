#include "core/modelling/pipe_network.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/curves/arc_length.h"
#include "core/error.h"
#include "core/modelling/pipe_junction.h"

namespace viscera::core {

PipeNetwork make_pipe_network(const std::vector<Vec3>& points, const std::vector<double>& radii) {
  PipeNetwork network;
  network.branches.push_back({points, radii, -1, 1.0});
  check_pipe_network(network, "pipe");
  return network;
}

void check_pipe_network(const PipeNetwork& network, const std::string& what) {
  if (network.branches.empty()) throw UsageError(what + ": a pipe needs at least one branch");
  for (std::size_t b = 0; b < network.branches.size(); ++b) {
    const PipeBranch& branch = network.branches[b];
    const std::string name = what + ": branch " + std::to_string(b);
    if (b == 0 && branch.parent != -1)
      throw UsageError(name + " is the root and cannot have a parent");
    if (b > 0 && (branch.parent < 0 || branch.parent >= static_cast<int>(b))) {
      throw UsageError(name + " must name an earlier branch as its parent, not " +
                       std::to_string(branch.parent));
    }
    if (branch.points.size() < (b == 0 ? 2U : 1U)) throw UsageError(name + " has too few points");
    if (branch.radii.size() != branch.points.size())
      throw UsageError(name + " needs one radius per point");
    if (!(branch.attach >= 0.0 && branch.attach <= 1.0))
      throw UsageError(name + " must attach at a fraction in [0, 1]");
  }
  if (!(network.blend >= 0.0 && network.blend <= 2.0))
    throw UsageError(what + ": junction blend must be in [0, 2]");
  for (std::size_t b = 0; b < network.branches.size(); ++b)
    check_pipe(branch_pipe(network, static_cast<int>(b)), what + ": branch " + std::to_string(b));
}

Vec3 attach_point(const PipeNetwork& network, int branch) {
  const PipeBranch& child = network.branches.at(static_cast<std::size_t>(branch));
  if (child.parent < 0) throw UsageError("branch " + std::to_string(branch) + " has no parent");
  const ArcLengthTable table(pipe_centre_line(branch_pipe(network, child.parent)));
  return table.curve().point(table.parameter_at(child.attach * table.length()));
}

PipePrimitive branch_pipe(const PipeNetwork& network, int branch) {
  const PipeBranch& b = network.branches.at(static_cast<std::size_t>(branch));
  PipePrimitive pipe;
  pipe.ring_segments = network.ring_segments;
  pipe.axial_spacing = network.axial_spacing;
  pipe.points = b.points;
  pipe.radii = b.radii;
  pipe.start_cap = network.start_cap;
  pipe.end_cap = network.end_cap;
  if (b.parent >= 0) {
    pipe.points.insert(pipe.points.begin(), attach_point(network, branch));
    pipe.radii.insert(pipe.radii.begin(), b.radii.empty() ? 0.0 : b.radii.front());
    pipe.start_cap = PipeCap::Flat;  // buried inside the parent
  }
  return pipe;
}

std::vector<Vec3> network_control_points(const PipeNetwork& network) {
  std::vector<Vec3> points;
  for (const auto& b : network.branches)
    points.insert(points.end(), b.points.begin(), b.points.end());
  return points;
}

std::pair<int, int> locate_control_point(const PipeNetwork& network, int index) {
  int first = 0;
  for (std::size_t b = 0; b < network.branches.size(); ++b) {
    const auto count = static_cast<int>(network.branches[b].points.size());
    if (index >= first && index < first + count) return {static_cast<int>(b), index - first};
    first += count;
  }
  throw UsageError("control point " + std::to_string(index) + " does not exist (the pipe has " +
                   std::to_string(first) + ")");
}

namespace {

/// Radius of branch b's parent at b's attach point.
double parent_radius_at_attach(const PipeNetwork& network, int branch) {
  const PipePrimitive parent =
      branch_pipe(network, network.branches[static_cast<std::size_t>(branch)].parent);
  const ArcLengthTable table(pipe_centre_line(parent));
  const double t = table.parameter_at(network.branches[static_cast<std::size_t>(branch)].attach *
                                      table.length());
  return pipe_radius_at(parent, table.curve(), t);
}

/// Labels each vertex with the branch whose tube surface is nearest.
std::vector<double> nearest_branch(const PipeNetwork& network, const SurfaceMesh& mesh) {
  struct Sample {
    Vec3 point;
    double radius;
    int branch;
  };
  std::vector<Sample> samples;
  for (std::size_t b = 0; b < network.branches.size(); ++b) {
    const PipePrimitive pipe = branch_pipe(network, static_cast<int>(b));
    const ArcLengthTable table(pipe_centre_line(pipe));
    const double mean_radius = pipe.radii.front();
    const int n = std::max(2, static_cast<int>(std::ceil(table.length() / (0.25 * mean_radius))));
    for (const double t : even_arc_length_parameters(table, n)) {
      samples.push_back(
          {table.curve().point(t), pipe_radius_at(pipe, table.curve(), t), static_cast<int>(b)});
    }
  }
  std::vector<double> label(mesh.vertices.size(), 0.0);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& s : samples) {
      const double d = std::abs((mesh.vertices[v] - s.point).norm() - s.radius);
      if (d < best) {
        best = d;
        label[v] = s.branch;
      }
    }
  }
  return label;
}

}  // namespace

SurfaceMesh tessellate_pipe_network(const PipeNetwork& network, Progress& progress) {
  check_pipe_network(network, "pipe");
  if (network.branches.size() == 1) {
    SurfaceMesh mesh = tessellate_pipe(branch_pipe(network, 0));
    mesh.vertex_attributes["branch"] = std::vector<double>(mesh.vertices.size(), 0.0);
    return mesh;
  }
  if (network.start_cap == PipeCap::Open || network.end_cap == PipeCap::Open) {
    throw UsageError(
        "a branching pipe needs closed caps: open tubes cannot be joined into one surface");
  }
  std::vector<JunctionTube> tubes;
  double edge = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < network.branches.size(); ++b) {
    const PipePrimitive pipe = branch_pipe(network, static_cast<int>(b));
    PipeSweepOptions sweep;
    double blend_width = 0.0;
    if (b > 0) {
      // The child starts on the parent's axis; continuing it straight back by half the
      // parent's radius keeps its start cap inside the parent even where it leaves at a
      // shallow angle or from the parent's end.
      sweep.start_extension = 0.5 * parent_radius_at_attach(network, static_cast<int>(b));
      blend_width = network.blend * pipe.radii.front();
    }
    SurfaceMesh tube = tessellate_pipe(pipe, sweep);
    tube.normals.clear();
    tube.uvs.clear();
    tube.vertex_attributes.clear();
    double mean_radius = 0.0;
    for (const double r : pipe.radii)
      mean_radius += r / static_cast<double>(pipe.radii.size());
    edge = std::min(edge, network.axial_spacing > 0.0
                              ? network.axial_spacing
                              : 2.0 * std::numbers::pi * mean_radius / network.ring_segments);
    tubes.push_back({std::move(tube), blend_width});
  }
  SurfaceMesh mesh = join_tubes(tubes, edge, progress);
  mesh.vertex_attributes["branch"] = nearest_branch(network, mesh);
  compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace viscera::core
