#pragma once
/// The per-spring half of a KisMo spring pass (seed 001 §3.2, eq. 1): each spring's pull and
/// energy, computed independently of the others so that a chunk of springs can be evaluated
/// four at a time. The pulls are added to the knots afterwards, in spring order
/// (kismo_mass_spring.cpp), so the forces do not depend on how the pulls were computed.
///
/// Decision: the four-wide path (AVX2, chosen at run time when the processor has it) performs
/// the same IEEE operations in the same order as the one-spring path — no fused multiply-add,
/// no reciprocal approximations — so both give the same bits and a session replays
/// bit-identically on machines with and without it.

#include <cstddef>
#include <span>

#include "core/math_types.h"
#include "simulator/physics/kismo_mass_spring.h"

namespace viscera::sim {

/// One spring's pull on its first knot in N (towards the second when stretched; the second
/// knot receives the opposite) and its stored energy in J. A spring of no length exerts
/// nothing and is marked by a negative energy.
struct SpringPull {
  double x, y, z;
  double energy;
};

/// How compute_spring_pulls evaluates the springs.
enum class SpringKernel {
  Best,        ///< four at a time when the processor supports AVX2, else one at a time
  OneAtATime,  ///< the reference
  FourWide,    ///< AVX2; only valid where four_wide_springs_supported()
};

/// Whether this processor runs SpringKernel::FourWide.
bool four_wide_springs_supported();

/// Pulls of springs [begin, end) into out[0 … end − begin): the cubic's pull along
/// d̂ = (x_j − x_i)/|x_j − x_i| and, when `damped` (springs.damping not empty), the damping
/// element's c (v_j − v_i)·d̂ along it.
void compute_spring_pulls(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                          const CubicSprings& springs, bool damped, std::size_t begin,
                          std::size_t end, SpringPull* out,
                          SpringKernel kernel = SpringKernel::Best);

}  // namespace viscera::sim
