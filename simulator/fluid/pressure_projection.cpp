#include "simulator/fluid/pressure_projection.h"

#include <algorithm>
#include <cmath>

#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

/// h·∇·u of the cells of line (j, k), the net outflow through their faces (m/s), into a
/// thread's buffer: contiguous loads from the six face lines around the cells.
const double* line_outflow(const FlowGrid& grid, int j, int k) {
  thread_local std::vector<double> outflow;
  const int nx = grid.nx();
  outflow.resize(static_cast<std::size_t>(nx));
  double* __restrict out = outflow.data();
  const double* u = grid.velocity(0).data() + grid.face_dims(0).index(0, j, k);
  const FaceDims dv = grid.face_dims(1);
  const double* v0 = grid.velocity(1).data() + dv.index(0, j, k);
  const double* v1 = grid.velocity(1).data() + dv.index(0, j + 1, k);
  for (int i = 0; i < nx; ++i)
    out[i] = u[i + 1] - u[i] + v1[i] - v0[i];
  if (grid.planar()) {
    for (int i = 0; i < nx; ++i)
      out[i] += 0.0;  // as the three-dimensional sum adds its w terms: the same zeros' signs
    return out;
  }
  const FaceDims dw = grid.face_dims(2);
  const double* w0 = grid.velocity(2).data() + dw.index(0, j, k);
  const double* w1 = grid.velocity(2).data() + dw.index(0, j, k + 1);
  for (int i = 0; i < nx; ++i)
    out[i] += w1[i] - w0[i];
  return out;
}

/// Largest |∇·u| over the fluid cells, 1/s: FlowGrid::max_divergence over the threads.
double largest_divergence(const FlowGrid& grid, int threads, std::vector<double>& line_largest) {
  const int nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
  line_largest.resize(static_cast<std::size_t>(ny * nz));
  for_each_line(ny, nz, threads, [&](int j, int k) {
    const double* outflow = line_outflow(grid, j, k);
    double m = 0.0;
    for (int i = 0; i < nx; ++i)
      if (grid.cell(i, j, k) == FlowCell::Fluid) m = std::max(m, std::abs(outflow[i]));
    line_largest[static_cast<std::size_t>(j + ny * k)] = m;
  });
  return *std::max_element(line_largest.begin(), line_largest.end()) / grid.cell_size();
}

}  // namespace

ProjectionResult PressureProjector::project(FlowGrid& grid, const ProjectionSettings& settings) {
  const int nx = grid.nx(), ny = grid.ny(), nz = grid.nz(), threads = settings.threads;
  const double h = grid.cell_size(), dt = settings.time_step;
  if (solver_ == nullptr || labelling_ != grid.labelling()) {
    solver_ = std::make_unique<MultigridPoisson>(grid);
    labelling_ = grid.labelling();
  }
  MultigridPoisson& solver = *solver_;
  std::vector<double>& p = grid.pressure();
  rhs_.assign(static_cast<std::size_t>(grid.cell_count()), 0.0);

  // b = −(h/Δt)·(h ∇·u) on the unknowns; a closed region's b must sum to zero.
  std::vector<double> partials;
  const double b_sum = sum_over_lines(ny, nz, threads, partials, [&](int j, int k) {
    const double* outflow = line_outflow(grid, j, k);
    double line = 0.0;
    for (int i = 0; i < nx; ++i) {
      const int c = grid.cell_index(i, j, k);
      if (!solver.unknown(c)) {
        p[static_cast<std::size_t>(c)] = 0.0;
        continue;
      }
      rhs_[static_cast<std::size_t>(c)] = -(h / dt) * outflow[i];
      line += rhs_[static_cast<std::size_t>(c)];
    }
    return line;
  });
  if (!solver.has_open()) {
    double unknowns = 0.0;
    for (int c = 0; c < grid.cell_count(); ++c)
      unknowns += solver.unknown(c) ? 1.0 : 0.0;
    if (unknowns > 0.0)
      for (int c = 0; c < grid.cell_count(); ++c)
        if (solver.unknown(c)) rhs_[static_cast<std::size_t>(c)] -= b_sum / unknowns;
  }

  // |b − A p| ≤ tol·h²/Δt bounds |∇·u| by tol.
  PoissonSolveSettings solve;
  solve.residual_tolerance = settings.divergence_tolerance * h * h / dt;
  solve.max_iterations = settings.max_iterations;
  solve.threads = threads;
  const PoissonSolveResult solved = solver.solve(rhs_, p, solve);
  ProjectionResult result;
  result.iterations = solved.iterations;
  result.converged = solved.converged;

  // u −= Δt ∇p on the active faces (p = 0 in open cells, solid faces untouched). p is 0 in
  // every cell that is not an unknown, so each line runs without branches; a face on the grid's
  // boundary has a cell outside the grid on one side and is never active.
  const double scale = dt / h;
  for (int axis = 0; axis < (grid.planar() ? 2 : 3); ++axis) {
    const FaceDims fd = grid.face_dims(axis);
    const auto& states = grid.face_states(axis);
    auto& velocity = grid.velocity(axis);
    const std::ptrdiff_t step = axis == 0 ? 1 : (axis == 1 ? nx : nx * ny);  // cell to cell
    for_each_line(fd.y, fd.z, threads, [&](int j, int k) {
      if ((axis == 1 && (j == 0 || j == ny)) || (axis == 2 && (k == 0 || k == nz))) return;
      const int first = axis == 0 ? 1 : 0;  // faces i = first … nx − 1 lie between two cells
      const auto face = static_cast<std::size_t>(fd.index(0, j, k));
      const auto cell = static_cast<std::size_t>(grid.cell_index(0, j, k));  // after face 0
      const FaceState* __restrict state = states.data() + face;
      double* __restrict u = velocity.data() + face;
      const double* __restrict pressure = p.data() + cell;
      for (std::ptrdiff_t i = first; i < nx; ++i)
        u[i] -= state[i] == FaceState::Active ? scale * (pressure[i] - pressure[i - step]) : 0.0;
    });
  }
  result.max_divergence = largest_divergence(grid, threads, partials);
  return result;
}

ProjectionResult project(FlowGrid& grid, const ProjectionSettings& settings) {
  PressureProjector projector;
  return projector.project(grid, settings);
}

}  // namespace viscera::sim::fluid
