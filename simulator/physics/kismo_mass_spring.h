#pragma once
/// KisMo mass-spring nets (Kühnapfel et al., KISMET; seed 001 §3.2, eq. 1–3). Knots on the
/// surface and inside an object are joined by springs whose force follows the cubic fitted to a
/// measured stress-strain curve; each knot has its own damping; a bounding matrix B_i says per
/// axis whether the knot moves. The net is integrated explicitly:
///   v_i^{k+1} = v_i^k + B_i · h/m_i · (F_ext,i − Σ_j f_ij − d_i v_i^k + m_i g)   (eq. 2)
///   u_i^{k+1} = u_i^k + h · v_i^{k+1}                                          (eq. 3)

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// Springs with a cubic force law in the strain ε = (|u_j − u_i| − l0) / l0:
/// f(ε) = k1 ε + k2 ε|ε| + k3 ε³ (N), pulling the knots together when stretched. ε|ε| keeps the
/// quadratic term odd, so compression pushes as hard as the same stretch pulls.
struct CubicSprings {
  std::vector<std::array<int, 2>> knots;
  std::vector<double> rest_length;                  ///< l0 in m
  std::vector<std::array<double, 3>> coefficients;  ///< k1, k2, k3 in N
  std::vector<double> damping;  ///< N·s/m of each spring's damping element, or empty for none
};

/// Spring coefficients from a stress-strain cubic σ(ε) = c1 ε + c2 ε² + c3 ε³ (Pa, seed 001
/// §3.2) for a spring that stands for `cross_section` m² of tissue: k_n = c_n · cross_section.
std::array<double, 3> spring_coefficients_from_cubic(const std::array<double, 3>& stress_cubic,
                                                     double cross_section);

/// The stored energy in J, E = l0 (k1 ε²/2 + k2 |ε|³/3 + k3 ε⁴/4) per spring.
double cubic_spring_energy(std::span<const core::Vec3> positions, const CubicSprings& springs);

/// Adds the spring forces to `forces` and returns the stored energy in J (as above).
double add_cubic_spring_forces(std::span<const core::Vec3> positions, const CubicSprings& springs,
                               std::span<core::Vec3> forces);

/// Adds the forces of the springs' damping elements (seed 001: "virtual springs and damping
/// elements"): −c (v_j − v_i)·d̂ d̂ on j and the opposite on i, with velocities in m/s.
void add_spring_damping_forces(std::span<const core::Vec3> positions,
                               std::span<const core::Vec3> velocities, const CubicSprings& springs,
                               std::span<core::Vec3> forces);

/// Both of the above in one pass over the springs (one length and one division per spring),
/// as an explicit integrator's sub-step needs them: adds the spring and damping forces to
/// `forces` and returns the springs' energy in J. Equal to add_spring_damping_forces then
/// add_cubic_spring_forces up to the order of the floating-point sums.
double add_damped_cubic_spring_forces(std::span<const core::Vec3> positions,
                                      std::span<const core::Vec3> velocities,
                                      const CubicSprings& springs, std::span<core::Vec3> forces);

/// Per-knot parameters of a net.
struct KnotParameters {
  std::vector<double> mass;                        ///< kg
  std::vector<double> damping;                     ///< d_i in N·s/m
  std::vector<std::array<std::uint8_t, 3>> bound;  ///< B_i: 1 where the axis moves, 0 where held
};

/// One step of eq. 2–3 with the forces already in `forces` (springs and external) plus
/// gravity `g` (m/s²). Held axes keep position and get zero velocity.
void kismo_step(std::span<core::Vec3> positions, std::span<core::Vec3> velocities,
                std::span<const core::Vec3> forces, const KnotParameters& knots,
                const core::Vec3& gravity, double h);

}  // namespace viscera::sim
