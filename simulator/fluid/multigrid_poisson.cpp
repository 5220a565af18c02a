#include "simulator/fluid/multigrid_poisson.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

constexpr std::uint8_t kSolid = static_cast<std::uint8_t>(FlowCell::Solid);
constexpr std::uint8_t kFluid = static_cast<std::uint8_t>(FlowCell::Fluid);

constexpr int kSweeps = 3;  ///< Jacobi sweeps before and after each coarse correction
/// The sweeps' weights: the reciprocals of the roots of the degree-3 Chebyshev polynomial on
/// [kSmoothedLow, 2] ∋ the eigenvalues of D⁻¹A, so that the three sweeps together damp every
/// component in that range by at most 1/T₃((2 + low)/(2 − low)) = 0.36 (Adams, Brezina, Hu &
/// Tuminaro 2003, "Parallel multigrid smoothing: polynomial versus Gauss–Seidel"). A product
/// of Jacobi steps is a polynomial in D⁻¹A, so the sweeps commute and the V-cycle stays
/// symmetric; |p(λ)| ≤ 1 on (0, 2], so it stays positive definite. Three sweeps at ω = ⅔
/// damp [⅓, 2] only by 0.47 and little below it; 0.15 rather than the textbook ⅓ also
/// damps the middle frequencies the cell-centred coarse correction leaves (BM_FlowStep 40³:
/// 4.3 CG iterations a step, against 4.6 for 0.2, 5.8 for ⅓ and 7.0 for ω = ⅔).
constexpr double kSmoothedLow = 0.15;
constexpr float kCoarsestWeight = 2.0f / 3.0f;
constexpr int kCoarsestSweeps = 30;  ///< on a level of at most 3 cells per axis

/// Weight of sweep `sweep` of kSweeps.
float smoothing_weight(int sweep) {
  const double centre = (2.0 + kSmoothedLow) / 2.0, half = (2.0 - kSmoothedLow) / 2.0;
  const double root = centre + half * std::cos((2 * sweep + 1) * std::numbers::pi / (2 * kSweeps));
  return static_cast<float>(1.0 / root);
}

/// Cell-centred trilinear transfer along one axis: the parent of fine index i and its other
/// neighbour, with weights ¾ and ¼; an axis that is not halved maps i to itself with weight 1.
struct AxisTransfer {
  int parent, neighbour;
  float parent_weight, neighbour_weight;
};

AxisTransfer axis_transfer(int i, bool halved) {
  if (!halved) return {i, i, 1.0f, 0.0f};
  const int parent = i / 2;
  return {parent, i % 2 == 0 ? parent - 1 : parent + 1, 0.75f, 0.25f};
}

/// Index of the largest of `values` (lines' maxima) — the largest residual.
double largest_of(const std::vector<double>& values) {
  double m = 0.0;
  for (const double v : values)
    m = std::max(m, v);
  return m;
}

/// One damped Jacobi update of cells [begin, end) of a level with face couplings, into out.
void weighted_jacobi_line(const float* __restrict x, const float* __restrict b,
                          const float* __restrict inverse, const float* __restrict diagonal,
                          const float* __restrict fx, const float* __restrict fy,
                          const float* __restrict fz, float* __restrict out, std::size_t begin,
                          std::size_t end, std::size_t sx, std::size_t sxy, float weight) {
  for (std::size_t c = begin; c < end; ++c) {
    const float ax =
        diagonal[c] * x[c] - (fx[c - 1] * x[c - 1] + fx[c] * x[c + 1] + fy[c - sx] * x[c - sx] +
                              fy[c] * x[c + sx] + fz[c - sxy] * x[c - sxy] + fz[c] * x[c + sxy]);
    out[c] = x[c] + weight * inverse[c] * (b[c] - ax);
  }
}

/// The renormalised residual (b − A x)·scale of cells [begin, end) of a level with face
/// couplings, into r.
void weighted_residual_line(const float* __restrict x, const float* __restrict b,
                            const float* __restrict diagonal, const float* __restrict fx,
                            const float* __restrict fy, const float* __restrict fz,
                            const float* __restrict scale, float* __restrict r, std::size_t begin,
                            std::size_t end, std::size_t sx, std::size_t sxy) {
  for (std::size_t c = begin; c < end; ++c)
    r[c] = (b[c] - (diagonal[c] * x[c] -
                    (fx[c - 1] * x[c - 1] + fx[c] * x[c + 1] + fy[c - sx] * x[c - sx] +
                     fy[c] * x[c + sx] + fz[c - sxy] * x[c - sxy] + fz[c] * x[c + sxy]))) *
           scale[c];
}

}  // namespace

MultigridPoisson::MultigridPoisson(const FlowGrid& grid) : planar_(grid.planar()) {
  restriction_scale_ = planar_ ? 1.0 : 0.5;
  std::vector<std::uint8_t> labels(static_cast<std::size_t>(grid.cell_count()));
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        const FlowCell cell = grid.cell(i, j, k);
        labels[static_cast<std::size_t>(grid.cell_index(i, j, k))] =
            static_cast<std::uint8_t>(cell);
        has_open_ = has_open_ || cell == FlowCell::Open;
      }
  levels_.emplace_back();
  build_finest(levels_.back(), grid.nx(), grid.ny(), grid.nz(), labels);
  for (;;) {
    const Level& fine = levels_.back();
    const int smallest =
        planar_ ? std::min(fine.nx, fine.ny) : std::min({fine.nx, fine.ny, fine.nz});
    if (smallest < 4) break;
    Level coarse;
    coarsen(fine, coarse);
    levels_.push_back(std::move(coarse));
  }
  const Level& finest = levels_.front();
  unknown_.assign(static_cast<std::size_t>(finest.nx) * finest.ny * finest.nz, 0);
  for (int k = 0, c = 0; k < finest.nz; ++k)
    for (int j = 0; j < finest.ny; ++j)
      for (int i = 0; i < finest.nx; ++i, ++c)
        unknown_[static_cast<std::size_t>(c)] = finest.inverse_diagonal[finest.at(i, j, k)] != 0.0f;
  // Each fine unknown's renormalisation over the parents that are unknowns.
  for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
    Level& fine = levels_[l];
    const Level& coarse = levels_[l + 1];
    for (int k = 0; k < fine.nz; ++k)
      for (int j = 0; j < fine.ny; ++j)
        for (int i = 0; i < fine.nx; ++i) {
          const std::size_t f = fine.at(i, j, k);
          if (fine.inverse_diagonal[f] == 0.0f) continue;
          const AxisTransfer tx = axis_transfer(i, true), ty = axis_transfer(j, true),
                             tz = axis_transfer(k, !planar_);
          float total = 0.0f;
          for (const auto& [ci, wi] : {std::pair{tx.parent, tx.parent_weight},
                                       std::pair{tx.neighbour, tx.neighbour_weight}})
            for (const auto& [cj, wj] : {std::pair{ty.parent, ty.parent_weight},
                                         std::pair{ty.neighbour, ty.neighbour_weight}})
              for (const auto& [ck, wk] : {std::pair{tz.parent, tz.parent_weight},
                                           std::pair{tz.neighbour, tz.neighbour_weight}})
                if (coarse.inverse_diagonal[coarse.at(ci, cj, ck)] != 0.0f) total += wi * wj * wk;
          fine.prolongation_scale[f] = total > 0.0f ? 1.0f / total : 0.0f;
        }
  }
  const std::size_t n = levels_.front().size();
  for (auto* v : {&rhs_, &p_, &r_, &d_, &q_})
    v->assign(n, 0.0);
}

namespace {

/// Sizes `level` for nx×ny×nz cells, every array zero.
template <typename Level>
void size_level(Level& level, int nx, int ny, int nz) {
  level.nx = nx, level.ny = ny, level.nz = nz;
  level.sx = nx + 3, level.sy = ny + 3;
  const auto size = static_cast<std::size_t>(level.sx * level.sy * (nz + 3));
  for (auto* v : {&level.diagonal, &level.inverse_diagonal, &level.prolongation_scale, &level.x,
                  &level.b, &level.r, &level.scratch})
    v->assign(size, 0.0f);
}

}  // namespace

void MultigridPoisson::build_finest(Level& level, int nx, int ny, int nz,
                                    const std::vector<std::uint8_t>& labels) {
  size_level(level, nx, ny, nz);
  const std::size_t size = level.size();
  std::vector<std::uint8_t> padded(size, kSolid);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        padded[level.at(i, j, k)] = labels[static_cast<std::size_t>(i + nx * (j + ny * k))];
  const std::size_t sx = static_cast<std::size_t>(level.sx), sxy = sx * level.sy;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = level.at(i, j, k);
        if (padded[c] != kFluid) continue;
        int sides = 0;
        for (const std::size_t n : {c - 1, c + 1, c - sx, c + sx, c - sxy, c + sxy})
          sides += padded[n] != kSolid;
        if (sides == 0) continue;  // a fluid pocket sealed by solid cells: no equation
        level.diagonal[c] = static_cast<Real>(sides);
        level.inverse_diagonal[c] = 1.0f / static_cast<Real>(sides);
      }
}

void MultigridPoisson::coarsen(const Level& fine, Level& coarse) const {
  size_level(coarse, (fine.nx + 1) / 2, (fine.ny + 1) / 2, planar_ ? 1 : (fine.nz + 1) / 2);
  for (auto* v : {&coarse.face_x, &coarse.face_y, &coarse.face_z})
    v->assign(coarse.size(), 0.0f);
  const std::size_t sx = static_cast<std::size_t>(fine.sx), sxy = sx * fine.sy;
  const bool unit = fine.face_x.empty();
  // −A between fine unknown f and its neighbour f + step along `axis`.
  const auto coupling = [&](std::size_t f, int axis, std::size_t step) -> Real {
    if (!unit) return (axis == 0 ? fine.face_x : axis == 1 ? fine.face_y : fine.face_z)[f];
    return fine.inverse_diagonal[f + step] != 0.0f ? 1.0f : 0.0f;
  };
  // (Pᵀ A P)_IJ with P the children's indicator: each child's diagonal, less twice each face
  // inside I, and each face between I and its next coarse cell along an axis.
  for (int k = 0; k < fine.nz; ++k)
    for (int j = 0; j < fine.ny; ++j)
      for (int i = 0; i < fine.nx; ++i) {
        const std::size_t f = fine.at(i, j, k);
        if (fine.inverse_diagonal[f] == 0.0f) continue;
        const std::size_t I = coarse.at(i / 2, j / 2, planar_ ? k : k / 2);
        coarse.diagonal[I] += fine.diagonal[f];
        const int index[3] = {i, j, k};
        const std::size_t steps[3] = {1, sx, sxy};
        std::vector<Real>* faces[3] = {&coarse.face_x, &coarse.face_y, &coarse.face_z};
        for (int axis = 0; axis < (planar_ ? 2 : 3); ++axis) {
          const Real a = coupling(f, axis, steps[axis]);
          if (index[axis] % 2 == 0)
            coarse.diagonal[I] -= 2.0f * a;  // both children in I
          else
            (*faces[axis])[I] += a;
        }
      }
  const Real scale = planar_ ? 0.5f : 0.25f;  // 2^(d−1) fine faces make one coarse face
  for (std::size_t c = 0; c < coarse.size(); ++c) {
    coarse.face_x[c] *= scale, coarse.face_y[c] *= scale, coarse.face_z[c] *= scale;
    // A sum of multiples of ¼, exact in single precision: 0 only for a pocket sealed inside I.
    coarse.diagonal[c] *= scale;
    if (coarse.diagonal[c] > 0.0f) coarse.inverse_diagonal[c] = 1.0f / coarse.diagonal[c];
  }
}

void MultigridPoisson::smooth(Level& level, int sweeps, bool from_zero, int threads) {
  // x stays 0 off the unknowns (their inverse diagonal is 0, and prolongation skips them), so
  // one branch-free update serves every cell and the compiler vectorises the line.
  const auto sx = static_cast<std::size_t>(level.sx), sxy = sx * static_cast<std::size_t>(level.sy);
  const auto nx = static_cast<std::size_t>(level.nx);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    const bool first = from_zero && sweep == 0;
    const float weight = sweeps == kSweeps ? smoothing_weight(sweep) : kCoarsestWeight;
    const Real* __restrict x = level.x.data();
    const Real* __restrict b = level.b.data();
    const Real* __restrict inverse = level.inverse_diagonal.data();
    const Real* __restrict diagonal = level.diagonal.data();
    Real* __restrict out = level.scratch.data();
    for_each_line(level.ny, level.nz, threads, [&](int j, int k) {
      const std::size_t row = level.at(0, j, k);
      if (first) {
        for (std::size_t c = row; c < row + nx; ++c)
          out[c] = weight * inverse[c] * b[c];
        return;
      }
      if (level.face_x.empty()) {
        for (std::size_t c = row; c < row + nx; ++c) {
          const Real ax = diagonal[c] * x[c] -
                          (x[c - 1] + x[c + 1] + x[c - sx] + x[c + sx] + x[c - sxy] + x[c + sxy]);
          out[c] = x[c] + weight * inverse[c] * (b[c] - ax);
        }
        return;
      }
      weighted_jacobi_line(level.x.data(), level.b.data(), inverse, diagonal, level.face_x.data(),
                           level.face_y.data(), level.face_z.data(), out, row, row + nx, sx, sxy,
                           weight);
    });
    std::swap(level.x, level.scratch);
  }
}

void MultigridPoisson::residual(Level& level, int threads) {
  for_each_line(level.ny, level.nz, threads, [&](int j, int k) {
    const std::size_t row = level.at(0, j, k);
    const auto sx = static_cast<std::size_t>(level.sx),
               sxy = sx * static_cast<std::size_t>(level.sy);
    const Real* __restrict x = level.x.data();
    const Real* __restrict b = level.b.data();
    const Real* __restrict diagonal = level.diagonal.data();
    const Real* __restrict scale = level.prolongation_scale.data();  // 0 off the unknowns
    Real* __restrict r = level.r.data();
    const std::size_t end = row + static_cast<std::size_t>(level.nx);
    if (level.face_x.empty()) {
      for (std::size_t c = row; c < end; ++c)
        r[c] = (b[c] - (diagonal[c] * x[c] -
                        (x[c - 1] + x[c + 1] + x[c - sx] + x[c + sx] + x[c - sxy] + x[c + sxy]))) *
               scale[c];
      return;
    }
    weighted_residual_line(x, b, diagonal, level.face_x.data(), level.face_y.data(),
                           level.face_z.data(), scale, r, row, end, sx, sxy);
  });
}

void MultigridPoisson::restrict_residual(const Level& fine, Level& coarse, int threads) {
  // fine.r already carries each fine cell's renormalisation: b_C = s Σ_f w_fC r_f / W_f, with
  // the weights ¼ ¾ ¾ ¼ per axis over fine indices 2I−1 … 2I+2. Separably, one axis at a time
  // (x into by_x, then y into by_xy, then z), 28 loads a coarse cell instead of 64.
  constexpr Real kWeights[4] = {0.25f, 0.75f, 0.75f, 0.25f};
  const auto scale = static_cast<Real>(restriction_scale_);
  const int cx = coarse.nx, cy = coarse.ny, cz = coarse.nz;
  // Fine rows 2J−1 … 2J+2 for every J: −1 … 2cy (planar: the one plane k = K).
  const int rows_y = 2 * cy + 2, rows_z = planar_ ? 1 : 2 * cz + 2, z0 = planar_ ? 0 : -1;
  auto& by_x = coarse.restricted_x;
  auto& by_xy = coarse.restricted_xy;
  by_x.resize(static_cast<std::size_t>(cx) * rows_y * rows_z);
  by_xy.resize(static_cast<std::size_t>(cx) * cy * rows_z);
  for_each_line(rows_y, rows_z, threads, [&](int y, int z) {
    const Real* r = &fine.r[fine.at(-1, y - 1, z + z0)];
    Real* out = &by_x[static_cast<std::size_t>(cx) * (y + rows_y * z)];
    for (int I = 0; I < cx; ++I) {
      const Real* q = r + 2 * I;
      out[I] = 0.25f * q[0] + 0.75f * q[1] + 0.75f * q[2] + 0.25f * q[3];
    }
  });
  for_each_line(cy, rows_z, threads, [&](int J, int z) {
    Real* out = &by_xy[static_cast<std::size_t>(cx) * (J + cy * z)];
    const Real* rows[4];
    for (int b = 0; b < 4; ++b)
      rows[b] = &by_x[static_cast<std::size_t>(cx) * (2 * J + b + rows_y * z)];
    for (int I = 0; I < cx; ++I)
      out[I] = kWeights[0] * rows[0][I] + kWeights[1] * rows[1][I] + kWeights[2] * rows[2][I] +
               kWeights[3] * rows[3][I];
  });
  for_each_line(cy, cz, threads, [&](int J, int K) {
    Real* b = &coarse.b[coarse.at(0, J, K)];
    const Real* inverse = &coarse.inverse_diagonal[coarse.at(0, J, K)];
    const Real* planes[4];
    const int taps = planar_ ? 1 : 4;
    for (int c = 0; c < taps; ++c)
      planes[c] = &by_xy[static_cast<std::size_t>(cx) * (J + cy * (planar_ ? K : 2 * K + c))];
    for (int I = 0; I < cx; ++I) {
      Real sum = planes[0][I];
      if (!planar_)
        sum = kWeights[0] * planes[0][I] + kWeights[1] * planes[1][I] + kWeights[2] * planes[2][I] +
              kWeights[3] * planes[3][I];
      b[I] = inverse[I] == 0.0f ? 0.0f : scale * sum;
    }
  });
}

void MultigridPoisson::prolong_add(const Level& coarse, Level& fine, int threads) {
  // Separable: each fine line first blends its coarse lines over y and z (two or four of them),
  // then each fine cell takes its two parents along x from that blend — three loads a fine cell
  // instead of eight. Off the unknowns the scale is 0 and x stays 0.
  const auto width = static_cast<std::size_t>(coarse.nx + 2);  // padded indices −1 … nx
  for_each_line(fine.ny, fine.nz, threads, [&](int j, int k) {
    thread_local std::vector<Real> blend;
    blend.resize(width);
    const AxisTransfer ty = axis_transfer(j, true), tz = axis_transfer(k, !planar_);
    const Real* y0z0 = &coarse.x[coarse.at(-1, ty.parent, tz.parent)];
    const Real* y1z0 = &coarse.x[coarse.at(-1, ty.neighbour, tz.parent)];
    const Real* y0z1 = &coarse.x[coarse.at(-1, ty.parent, tz.neighbour)];
    const Real* y1z1 = &coarse.x[coarse.at(-1, ty.neighbour, tz.neighbour)];
    const Real a = ty.parent_weight * tz.parent_weight, b = ty.neighbour_weight * tz.parent_weight,
               c = ty.parent_weight * tz.neighbour_weight,
               d = ty.neighbour_weight * tz.neighbour_weight;
    for (std::size_t I = 0; I < width; ++I)
      blend[I] = a * y0z0[I] + b * y1z0[I] + c * y0z1[I] + d * y1z1[I];
    const std::size_t row = fine.at(0, j, k);
    Real* __restrict x = &fine.x[row];
    const Real* __restrict scale = &fine.prolongation_scale[row];
    const Real* __restrict parent = blend.data() + 1;  // parent[I], I = −1 … coarse nx
    // Fine cells 2I and 2I + 1 share parent I; the other parent is I − 1 and I + 1. In pairs,
    // with no division, so the loop vectorises; an odd fine line ends on a lone even cell
    // (the padding past it is a solid cell whose scale is 0).
    const int pairs = fine.nx / 2;
    for (int I = 0; I < pairs; ++I) {
      x[2 * I] += scale[2 * I] * (0.75f * parent[I] + 0.25f * parent[I - 1]);
      x[2 * I + 1] += scale[2 * I + 1] * (0.75f * parent[I] + 0.25f * parent[I + 1]);
    }
    if (fine.nx % 2 != 0)
      x[2 * pairs] += scale[2 * pairs] * (0.75f * parent[pairs] + 0.25f * parent[pairs - 1]);
  });
}

void MultigridPoisson::vcycle(std::size_t l, int threads) {
  Level& level = levels_[l];
  if (l + 1 == levels_.size()) {
    smooth(level, kCoarsestSweeps, true, threads);
    return;
  }
  smooth(level, kSweeps, true, threads);
  residual(level, threads);
  restrict_residual(level, levels_[l + 1], threads);
  vcycle(l + 1, threads);
  prolong_add(levels_[l + 1], level, threads);
  smooth(level, kSweeps, false, threads);
}

void MultigridPoisson::remove_mean(std::vector<Real>& v, const Level& level) const {
  double sum = 0.0, count = 0.0;
  for (std::size_t c = 0; c < level.size(); ++c)
    if (level.inverse_diagonal[c] != 0.0f) sum += static_cast<double>(v[c]), count += 1.0;
  if (count == 0.0) return;
  const auto mean = static_cast<Real>(sum / count);
  for (std::size_t c = 0; c < level.size(); ++c)
    if (level.inverse_diagonal[c] != 0.0f) v[c] -= mean;
}

PoissonSolveResult MultigridPoisson::solve(const std::vector<double>& b, std::vector<double>& p,
                                           const PoissonSolveSettings& settings) {
  Level& fine = levels_.front();
  const int threads = settings.threads;
  const std::size_t nx = static_cast<std::size_t>(fine.nx);
  line_largest_.resize(static_cast<std::size_t>(fine.ny * fine.nz));
  // Into the padded layout: p from the guess and the right-hand side, both 0 off the unknowns.
  for_each_line(fine.ny, fine.nz, threads, [&](int j, int k) {
    const std::size_t row = fine.at(0, j, k);
    const std::size_t cell = static_cast<std::size_t>(fine.nx * (j + fine.ny * k));
    for (std::size_t i = 0; i < nx; ++i) {
      const bool unknown = fine.inverse_diagonal[row + i] != 0.0f;
      p_[row + i] = unknown ? p[cell + i] : 0.0;
      rhs_[row + i] = unknown ? b[cell + i] : 0.0;
    }
  });
  const auto line_index = [&](int j, int k) { return static_cast<std::size_t>(j + fine.ny * k); };
  // r = b − A p, the V-cycle's right-hand side (r in single precision) and the line's largest
  // |r|. Each pass that changes r writes the V-cycle's copy too: no pass of its own.
  Real* __restrict vcycle_rhs = fine.b.data();
  for_each_line(fine.ny, fine.nz, threads, [&](int j, int k) {
    const std::size_t row = fine.at(0, j, k);
    double m = 0.0;
    for (std::size_t c = row; c < row + nx; ++c) {
      r_[c] = fine.inverse_diagonal[c] == 0.0f ? 0.0 : rhs_[c] - apply(fine, p_, c);
      vcycle_rhs[c] = static_cast<Real>(r_[c]);
      m = std::max(m, std::abs(r_[c]));
    }
    line_largest_[line_index(j, k)] = m;
  });
  double largest = largest_of(line_largest_);
  // z = M r (one single-precision V-cycle, left in fine.x and read from there); returns r·z.
  const auto precondition = [&] {
    vcycle(0, threads);
    if (!has_open_) remove_mean(fine.x, fine);
    return sum_over_lines(fine.ny, fine.nz, threads, partials_, [&](int j, int k) {
      const std::size_t row = fine.at(0, j, k);
      double s = 0.0;
      for (std::size_t c = row; c < row + nx; ++c)
        s += r_[c] * static_cast<double>(fine.x[c]);
      return s;
    });
  };
  // d = z + β d, or d = z to start.
  const auto update_direction = [&](bool first, double beta) {
    for_each_line(fine.ny, fine.nz, threads, [&](int j, int k) {
      const std::size_t row = fine.at(0, j, k);
      const Real* __restrict z = fine.x.data();
      if (first) {
        for (std::size_t c = row; c < row + nx; ++c)
          d_[c] = static_cast<double>(z[c]);
        return;
      }
      for (std::size_t c = row; c < row + nx; ++c)
        d_[c] = static_cast<double>(z[c]) + beta * d_[c];
    });
  };
  PoissonSolveResult result;
  if (largest > settings.residual_tolerance) {
    double rz = precondition();
    update_direction(true, 0.0);
    while (result.iterations < settings.max_iterations) {
      const double dq = sum_over_lines(fine.ny, fine.nz, threads, partials_, [&](int j, int k) {
        const std::size_t row = fine.at(0, j, k);
        double s = 0.0;
        for (std::size_t c = row; c < row + nx; ++c) {
          q_[c] = fine.inverse_diagonal[c] == 0.0f ? 0.0 : apply(fine, d_, c);
          s += d_[c] * q_[c];
        }
        return s;
      });
      if (!(dq > 0.0)) break;
      const double alpha = rz / dq;
      for_each_line(fine.ny, fine.nz, threads, [&](int j, int k) {
        const std::size_t row = fine.at(0, j, k);
        double m = 0.0;
        for (std::size_t c = row; c < row + nx; ++c) {
          p_[c] += alpha * d_[c];
          r_[c] -= alpha * q_[c];
          vcycle_rhs[c] = static_cast<Real>(r_[c]);
          m = std::max(m, std::abs(r_[c]));
        }
        line_largest_[line_index(j, k)] = m;
      });
      ++result.iterations;
      largest = largest_of(line_largest_);
      if (largest <= settings.residual_tolerance) break;
      const double rz_next = precondition();
      const double beta = rz_next / rz;
      rz = rz_next;
      update_direction(false, beta);
    }
  }
  result.largest_residual = largest;
  result.converged = largest <= settings.residual_tolerance;
  // Back to the grid's layout.
  for_each_line(fine.ny, fine.nz, threads, [&](int j, int k) {
    const std::size_t row = fine.at(0, j, k);
    const std::size_t cell = static_cast<std::size_t>(fine.nx * (j + fine.ny * k));
    for (std::size_t i = 0; i < nx; ++i)
      p[cell + i] = p_[row + i];
  });
  return result;
}

}  // namespace viscera::sim::fluid
