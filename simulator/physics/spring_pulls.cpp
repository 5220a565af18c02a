#include "simulator/physics/spring_pulls.h"

#include <cmath>

#include "core/error.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define VISCERA_FOUR_WIDE_SPRINGS 1
#endif

namespace viscera::sim {
namespace {

constexpr double kThird = 1.0 / 3.0;

/// One spring, in the operation order the four-wide path repeats lane by lane.
template <bool kDamped>
SpringPull one_spring(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                      const CubicSprings& springs, std::size_t s) {
  const auto [i, j] = springs.knots[s];
  const core::Vec3 d = x[j] - x[i];
  const double length = std::sqrt((d.x() * d.x() + d.y() * d.y()) + d.z() * d.z());
  if (length <= 0.0) return {0.0, 0.0, 0.0, -1.0};
  const double l0 = springs.rest_length[s];
  const double e = (length - l0) / l0, a = std::abs(e);
  const auto& k = springs.coefficients[s];
  const double energy =
      l0 * ((k[0] * e * e * 0.5 + k[1] * a * a * a * kThird) + k[2] * e * e * e * e * 0.25);
  const double inverse = 1.0 / length;
  double magnitude = (k[0] * e + k[1] * e * a) + k[2] * e * e * e;
  if constexpr (kDamped) {
    const core::Vec3 w = v[j] - v[i];
    magnitude += springs.damping[s] * ((w.x() * d.x() + w.y() * d.y()) + w.z() * d.z()) * inverse;
  }
  const double scale = magnitude * inverse;
  return {scale * d.x(), scale * d.y(), scale * d.z(), energy};
}

template <bool kDamped>
void one_at_a_time(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                   const CubicSprings& springs, std::size_t begin, std::size_t end,
                   SpringPull* out) {
  for (std::size_t s = begin; s < end; ++s)
    out[s - begin] = one_spring<kDamped>(x, v, springs, s);
}

#ifdef VISCERA_FOUR_WIDE_SPRINGS

#define VISCERA_AVX2 __attribute__((target("avx2"), always_inline)) inline

/// Rows r0…r3 become columns: r_k[l] ← r_l[k].
VISCERA_AVX2 void transpose(__m256d& r0, __m256d& r1, __m256d& r2, __m256d& r3) {
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
  r0 = _mm256_permute2f128_pd(t0, t2, 0x20);
  r1 = _mm256_permute2f128_pd(t1, t3, 0x20);
  r2 = _mm256_permute2f128_pd(t0, t2, 0x31);
  r3 = _mm256_permute2f128_pd(t1, t3, 0x31);
}

/// The three doubles at p (the fourth lane zero, never read: p may be the array's last triple).
VISCERA_AVX2 __m256d load3(const double* p) {
  return _mm256_maskload_pd(p, _mm256_set_epi64x(0, -1, -1, -1));
}

/// x, y, z of the difference b − a of four pairs of triples, one component per vector.
VISCERA_AVX2 void differences(const double* base, const int* pairs, __m256d& dx, __m256d& dy,
                              __m256d& dz) {
  __m256d r[4];
  for (int l = 0; l < 4; ++l)
    r[l] = _mm256_sub_pd(load3(base + 3 * static_cast<std::ptrdiff_t>(pairs[2 * l + 1])),
                         load3(base + 3 * static_cast<std::ptrdiff_t>(pairs[2 * l])));
  transpose(r[0], r[1], r[2], r[3]);
  dx = r[0];
  dy = r[1];
  dz = r[2];
}

VISCERA_AVX2 __m256d mul(__m256d a, __m256d b) {
  return _mm256_mul_pd(a, b);
}
VISCERA_AVX2 __m256d add(__m256d a, __m256d b) {
  return _mm256_add_pd(a, b);
}

template <bool kDamped>
__attribute__((target("avx2"))) void four_wide(std::span<const core::Vec3> x,
                                               std::span<const core::Vec3> v,
                                               const CubicSprings& springs, std::size_t begin,
                                               std::size_t end, SpringPull* out) {
  const double* px = x.data()->data();
  const double* pv = kDamped ? v.data()->data() : nullptr;
  const int* knots = springs.knots.data()->data();
  const double* rest = springs.rest_length.data();
  const double* coefficients = springs.coefficients.data()->data();
  const __m256d sign = _mm256_set1_pd(-0.0), zero = _mm256_setzero_pd();
  const __m256d half = _mm256_set1_pd(0.5), quarter = _mm256_set1_pd(0.25);
  const __m256d third = _mm256_set1_pd(kThird), one = _mm256_set1_pd(1.0);
  const __m256d none = _mm256_set1_pd(-1.0);
  std::size_t s = begin;
  for (; s + 4 <= end; s += 4) {
    const int* pairs = knots + 2 * s;
    __m256d dx, dy, dz;
    differences(px, pairs, dx, dy, dz);
    __m256d k[4];
    for (int l = 0; l < 4; ++l)
      k[l] = load3(coefficients + 3 * (s + static_cast<std::size_t>(l)));
    transpose(k[0], k[1], k[2], k[3]);
    const __m256d length = _mm256_sqrt_pd(add(add(mul(dx, dx), mul(dy, dy)), mul(dz, dz)));
    const __m256d l0 = _mm256_loadu_pd(rest + s);
    const __m256d e = _mm256_div_pd(_mm256_sub_pd(length, l0), l0);
    const __m256d a = _mm256_andnot_pd(sign, e);
    const __m256d k0e = mul(k[0], e), k1e = mul(k[1], e), k2ee = mul(mul(k[2], e), e);
    const __m256d energy =
        mul(l0, add(add(mul(mul(k0e, e), half), mul(mul(mul(mul(k[1], a), a), a), third)),
                    mul(mul(mul(k2ee, e), e), quarter)));
    const __m256d inverse = _mm256_div_pd(one, length);
    __m256d magnitude = add(add(k0e, mul(k1e, a)), mul(k2ee, e));
    if constexpr (kDamped) {
      __m256d wx, wy, wz;
      differences(pv, pairs, wx, wy, wz);
      const __m256d dot = add(add(mul(wx, dx), mul(wy, dy)), mul(wz, dz));
      magnitude =
          add(magnitude, mul(mul(_mm256_loadu_pd(springs.damping.data() + s), dot), inverse));
    }
    // A spring of no length (length ≤ 0 false also for NaN, as in one_spring) exerts nothing.
    const __m256d exerts = _mm256_cmp_pd(length, zero, _CMP_NLE_UQ);
    const __m256d scale = _mm256_and_pd(mul(magnitude, inverse), exerts);
    __m256d r0 = mul(scale, dx), r1 = mul(scale, dy), r2 = mul(scale, dz);
    __m256d r3 = _mm256_blendv_pd(none, energy, exerts);
    transpose(r0, r1, r2, r3);
    double* o = &out[s - begin].x;
    _mm256_storeu_pd(o, r0);
    _mm256_storeu_pd(o + 4, r1);
    _mm256_storeu_pd(o + 8, r2);
    _mm256_storeu_pd(o + 12, r3);
  }
  one_at_a_time<kDamped>(x, v, springs, s, end, out + (s - begin));
}

#endif

}  // namespace

bool four_wide_springs_supported() {
#ifdef VISCERA_FOUR_WIDE_SPRINGS
  static const bool supported = __builtin_cpu_supports("avx2");
  return supported;
#else
  return false;
#endif
}

void compute_spring_pulls(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                          const CubicSprings& springs, bool damped, std::size_t begin,
                          std::size_t end, SpringPull* out, SpringKernel kernel) {
  static_assert(sizeof(SpringPull) == 4 * sizeof(double));
  static_assert(sizeof(core::Vec3) == 3 * sizeof(double));
  const bool wide = kernel == SpringKernel::FourWide ||
                    (kernel == SpringKernel::Best && four_wide_springs_supported());
  if (wide && !four_wide_springs_supported())
    throw core::UsageError("the four-wide spring kernel needs a processor with AVX2");
#ifdef VISCERA_FOUR_WIDE_SPRINGS
  if (wide) {
    if (damped)
      four_wide<true>(x, v, springs, begin, end, out);
    else
      four_wide<false>(x, v, springs, begin, end, out);
    return;
  }
#endif
  if (damped)
    one_at_a_time<true>(x, v, springs, begin, end, out);
  else
    one_at_a_time<false>(x, v, springs, begin, end, out);
}

}  // namespace viscera::sim
