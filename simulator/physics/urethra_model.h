#pragma once
/// The urethra of the NTUA urological trainer (seed 002 §3, §5): a tube of circular sections on
/// the parabolic centre line y = a z², widened by the endoscope through a moving deformation,
/// and a fast force model that the haptic device renders — Coulomb and viscous friction and
/// wall springs along the endoscope axis (eq. 6–8) and rotational springs and friction for the
/// torques Tx, Ty, Tz (eq. 9–13) — with force bars and warnings near the tissue-break limits.
/// Coordinates: z along the urethra from the meatus (z = 0) to the bladder entrance, y up,
/// x to the side; the endoscope stays in the body's plane of symmetry y–z.

#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/mesh/surface_mesh.h"

namespace viscera::sim {

/// Geometry and tissue parameters. Lengths in m, stiffness in N/m, angles in rad.
struct UrethraParameters {
  double curvature = 13.0;          ///< a in y = a z², 1/m (seed 002: 0.13 per cm)
  double length = 0.16;             ///< m along z to the bladder entrance
  double radius = 0.001;            ///< undeformed lumen radius, m
  double endoscope_radius = 0.004;  ///< m (seed 002: four times the urethra's)
  int points_per_section = 9;       ///< n
  int basic_sections = 26;          ///< w
  double transition_length =
      0.012;  ///< m of the moving deformation ahead of the tip (ten subsections)
  double spring_stiffness = 15.0;  ///< k of each of the n − 1 wall springs per section, N/m
  double free_length = 0.04;       ///< m of urethra outside the body, where torques vanish
  double friction = 0.3;           ///< μ
  double viscous_friction = 2.0;   ///< b_V, N·s/m
  double viscous_torque_friction = 2e-4;   ///< b_ω, N·m·s
  double tip_rotational_stiffness = 0.05;  ///< N·m/rad at full insertion, for Tx (part 1) and Ty
  double bladder_rotational_stiffness = 0.02;  ///< N·m/rad of the spring at the bladder entrance
  double break_force = 4.0;                    ///< N along the axis beyond which tissue tears
  double break_torque = 0.08;                  ///< N·m beyond which tissue tears
  double warning_fraction = 0.8;               ///< warn from this fraction of a break limit
};

/// The endoscope as the device reports it.
struct EndoscopeState {
  core::Vec3 tip = core::Vec3::Zero();       ///< m
  double pitch = 0.0;                        ///< θx: rotation about x, rad (0 = along +z)
  double yaw = 0.0;                          ///< θy: rotation about y out of the y–z plane, rad
  core::Vec3 velocity = core::Vec3::Zero();  ///< of the tip relative to the tissue, m/s
  double spin_rate = 0.0;                    ///< ω about the endoscope axis, rad/s
};

/// Forces and torques on the endoscope (seed 002 eq. 6–13) and what the trainee is shown.
struct UrethraFeedback {
  double normal_force = 0.0;              ///< N, the wall springs pressing on the shaft
  double coulomb_friction = 0.0;          ///< F1 along the axis, N (negative = against insertion)
  double viscous_friction = 0.0;          ///< F2 along the axis, N
  double wall_resistance = 0.0;           ///< F3 along the axis, N
  core::Vec3 force = core::Vec3::Zero();  ///< F_re = F1 + F2 + F3 along the axis (y, z), N
  double torque_x = 0.0, torque_y = 0.0, torque_z = 0.0;  ///< N·m
  /// Bars of seed 002 Fig. 11 as fractions of the break limits: green Tx, blue Ty, yellow Tz,
  /// red F_re.
  double bar_tx = 0.0, bar_ty = 0.0, bar_tz = 0.0, bar_force = 0.0;
  std::vector<std::string> warnings;  ///< e.g. "axial force near the tissue-break limit"
};

/// One section of the lattice: its centre, unit normal (the tube direction) and n points.
struct UrethraSection {
  core::Vec3 centre = core::Vec3::Zero();
  core::Vec3 normal = core::Vec3::UnitZ();
  double radius = 0.0;
  std::vector<core::Vec3> points;
};

/// The urethra lattice and force model.
class UrethraModel {
 public:
  explicit UrethraModel(const UrethraParameters& parameters = {});

  const UrethraParameters& parameters() const { return p_; }
  /// Point of the centre line at z: (0, a z², z).
  core::Vec3 centre_line(double z) const;
  /// Unit tangent of the centre line at z.
  core::Vec3 tangent(double z) const;

  /// The sections for an endoscope tip at axial position `tip_z`: the basic sections, widened to
  /// the endoscope behind the tip, and the dense sections of the moving deformation ahead of it
  /// with a sinusoidal radius profile from the endoscope's radius to the urethra's (seed 002
  /// §3.2). Sorted by z.
  std::vector<UrethraSection> lattice(double tip_z) const;

  /// The lattice for an endoscope off the centre line (seed 002 §3.2 (b)–(c)): sections the
  /// scope has passed sit on its straight shaft, normal to it; the moving deformation follows
  /// the tip; the basic sections ahead share the tip's offset dy and tilt dθx, the offset
  /// falling linearly to zero at the fixed bladder entrance and the tilt to dθx / K there (K
  /// downstream sections).
  std::vector<UrethraSection> lattice(const EndoscopeState& endoscope) const;

  /// The urethra wall for a tip at `tip_z`: the lattice of lattice(tip_z) interpolated by
  /// piecewise Bézier curves with chord-length Catmull-Rom control points, closed around each
  /// section and open along the tube (seed 002 §3.1), sampled `around` and `along` times per
  /// segment. An open tube with UVs (u around, v along) and outward normals.
  core::SurfaceMesh surface(double tip_z, int around = 4, int along = 4) const;
  /// The same for an endoscope anywhere (see lattice(const EndoscopeState&)).
  core::SurfaceMesh surface(const EndoscopeState& endoscope, int around = 4, int along = 4) const;

  /// Forces and torques for the endoscope `state`.
  UrethraFeedback feedback(const EndoscopeState& state) const;

 private:
  /// Radius of the lumen at distance d ≥ 0 ahead of the tip (sinusoidal transition).
  double widened_radius(double ahead) const;
  /// How far into the constrained part the tip is, 0 … 1.
  double insertion_fraction(double tip_z) const;

  UrethraParameters p_;
  std::vector<double> section_z_;
};

}  // namespace viscera::sim
