#pragma once
/// The parts of a Scenario other than objects and materials (DESIGN.md §3). Lean for now;
/// every part exists, serialises and round-trips so later issues can fill it in.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "core/math_types.h"

namespace viscera::core {

/// A procedural texture applied to objects; baked maps are package files.
struct TextureSpec {
  std::string id;
  std::string preset;  ///< e.g. "endometrium"
  std::uint64_t seed = 0;
  int width = 512, height = 512;            ///< pixels
  std::map<std::string, std::string> maps;  ///< "albedo"|"normal"|"specular" → package path

  bool operator==(const TextureSpec&) const = default;
};

/// One cylindrical segment of a vessel tree. Positions in m, radius in m, flow in m³/s.
struct VesselSegment {
  int id = 0;
  int parent = -1;  ///< index of the parent segment, -1 for the root
  Vec3 proximal = Vec3::Zero();
  Vec3 distal = Vec3::Zero();
  double radius = 0.0;
  double flow = 0.0;

  bool operator==(const VesselSegment&) const = default;
};

/// A vessel tree hosted by an object.
struct VesselTree {
  std::string id;
  std::string host_object;
  std::string kind = "arterial";  ///< "arterial" | "venous"
  std::vector<VesselSegment> segments;

  bool operator==(const VesselTree&) const = default;
};

/// Pulse waves along a vessel tree (seed 001 §5).
struct PulseSpec {
  std::string vessel_tree;
  double heart_rate = 70.0;     ///< beats per minute
  double pulse_velocity = 5.0;  ///< m/s
  double wall_force = 0.05;     ///< N

  bool operator==(const PulseSpec&) const = default;
};

/// Organ motility: travelling contraction waves plus impulsive contractions (seed 001 §5).
struct MotilitySpec {
  double amplitude_mean = 0.002;    ///< m
  double amplitude_variance = 0.0;  ///< m²
  double wave_speed = 0.01;         ///< m/s
  Vec3 wave_direction = Vec3::UnitX();
  double frequency = 0.1;                      ///< Hz
  double frequency_disturbance = 0.0;          ///< Hz
  double contraction_interval_mean = 0.0;      ///< s, 0 = none
  double contraction_interval_variance = 0.0;  ///< s²

  bool operator==(const MotilitySpec&) const = default;
};

/// An active deformation of one object.
struct ActiveDeformation {
  std::string id;
  std::string target_object;
  std::variant<PulseSpec, MotilitySpec> spec;

  bool operator==(const ActiveDeformation&) const = default;
};

/// A pathology placed on or in a host organ; its geometry is its own scene object.
struct Pathology {
  std::string id;
  std::string kind;  ///< "myoma-submucosal" | "myoma-intramural" | "myoma-pedunculated" | "polyp" |
                     ///< "adhesion"
  std::string host_object;
  std::string object;            ///< scene object holding its geometry, or empty
  Vec3 position = Vec3::Zero();  ///< m
  double size = 0.0;             ///< m, characteristic diameter

  bool operator==(const Pathology&) const = default;
};

/// Two objects joined at pairs of nodes of their bodies (seed 001: nearest knots).
struct Connection {
  std::string id;
  std::string object_a, object_b;
  std::vector<std::array<int, 2>> node_pairs;
  double stiffness = 100.0;  ///< N/m per pair

  bool operator==(const Connection&) const = default;
};

/// Distension fluid set-up (seed 000 §2). Pressures in Pa.
struct FluidSpec {
  bool enabled = false;
  std::string medium = "saline";
  double inflow_pressure = 13332.0;  ///< Pa (100 mmHg)
  double outflow_pressure = 0.0;     ///< Pa
  double overload_volume = 1.0e-3;   ///< m³ of deficit that ends a session

  bool operator==(const FluidSpec&) const = default;
};

/// One task of a procedure (seed 000 §11: steps → substeps → tasks).
struct TaskSpec {
  std::string id;
  std::string name;
  std::string kind;  ///< what completes it, e.g. "observe", "reach", "settle"
  nlohmann::json parameters = nlohmann::json::object();

  bool operator==(const TaskSpec&) const = default;
};

/// A substep of a procedure (seed 000 §11, e.g. "identify the right tubal orifice"): the tasks
/// that complete it.
struct SubstepSpec {
  std::string id;
  std::string name;
  std::vector<TaskSpec> tasks;

  bool operator==(const SubstepSpec&) const = default;
};

/// A surgical step (seed 000 §11, e.g. "inspect the uterine cavity"). Steps are done in order;
/// the substeps and tasks inside a step in any order.
struct StepSpec {
  std::string id;
  std::string name;
  std::vector<SubstepSpec> substeps;

  bool operator==(const StepSpec&) const = default;
};

/// The instrument a procedure is trained with. Angles in degrees, lengths in m.
struct InstrumentSpec {
  std::string kind =
      "probe";  ///< "hysteroscope", "cystoscope", "laparoscope", "probe", "grasper", …
  double optics_angle = 0.0;         ///< viewing direction against the shaft axis (0, 12, 30 °)
  double field_of_view = 70.0;       ///< full opening angle of the optics, °
  double shaft_diameter = 0.004;     ///< m
  double focus_distance = 0.015;     ///< m, sharpest distance of the optics
  double min_view_distance = 0.003;  ///< m, closer than this the view is lost ("red-out")
  double max_view_distance = 0.04;   ///< m, beyond this the surface is too far to assess

  bool operator==(const InstrumentSpec&) const = default;
};

/// How a session on this scenario runs and is scored.
struct SessionSpec {
  double time_step = 1.0e-3;             ///< s, the fixed physics step
  double duration_limit = 600.0;         ///< s
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  ///< m/s²
  double contact_stiffness = 500.0;      ///< N/m per colliding point (penalty response)
  std::vector<TaskSpec> tasks;
  std::vector<std::string> metrics;
  /// The shipped procedure definition these steps came from (core::procedure_definition), or "".
  std::string procedure_definition;
  InstrumentSpec instrument;
  /// Steps → substeps → tasks (seed 000 §11); `tasks` above holds tasks outside any step.
  std::vector<StepSpec> steps;
  double force_warning = 0.0;  ///< N on the instrument that starts a warning; 0: none
  /// m the tool may push into the wall before it perforates; 0: the local wall thickness.
  double perforation_depth = 0.0;

  bool operator==(const SessionSpec&) const = default;
};

/// A named anatomical point that procedures and tasks refer to (e.g. "identify the right tubal
/// orifice", seed 000 §11): where it is and from which side it is seen.
struct Landmark {
  std::string id;  ///< e.g. "tubal-orifice-right", "cervix-internal-os", "fundus"
  std::string name;
  std::string object;            ///< the object whose surface it lies on
  Vec3 position = Vec3::Zero();  ///< m
  Vec3 normal =
      Vec3::Zero();  ///< unit, pointing away from the tissue (where a camera looks from), or zero

  bool operator==(const Landmark&) const = default;
};

/// One kind of cell of an agent-based tissue (seed 003 §V, the ten state constants).
struct CellTypeSpec {
  std::string id;
  double mass = 1e-4;                  ///< kg
  double radius = 0.001;               ///< m, for collisions
  double home_stiffness = 0.5;         ///< N/m, spring to the home position
  double connection_stiffness = 20.0;  ///< N/m, spring to each neighbour
  double damping = 0.05;               ///< fraction of velocity removed per step (0–1)
  double collision_efficiency = 0.5;   ///< k_collision
  double tear_strain = 1.0;            ///< connections stretched beyond this break
  double yield_strain = 0.5;           ///< beyond this rest lengths grow (plasticity)

  bool operator==(const CellTypeSpec&) const = default;
};

/// Cell-agent tissue laid out as data (seed 003 §V): the object's body nodes are the cells (their
/// home positions, masses and fixed flags); this says which type each cell is and how cells find
/// their neighbours at start-up.
struct CellTissueSpec {
  std::string object;
  std::vector<CellTypeSpec> types;
  std::vector<int> cell_types;    ///< index into types, one per body node
  double neighbour_radius = 0.0;  ///< m
  int max_neighbours = 4;         ///< seed 003: four in a sheet
  bool planar = true;             ///< cells stay in their z plane

  bool operator==(const CellTissueSpec&) const = default;
};

/// The urethra lattice of the NTUA trainer (seed 002 §3.1, §5): w circular sections of n points
/// on the centre line y = a z², and its force-model constants. The object's body nodes are the
/// lattice points, section by section; the bladder-entrance section is fixed.
struct UrethraLatticeSpec {
  std::string object;
  double curvature = 13.0;          ///< a, 1/m (seed 002: 0.13 per cm)
  double length = 0.16;             ///< m along z from the meatus to the bladder entrance
  double radius = 0.001;            ///< undeformed lumen radius, m
  int points_per_section = 9;       ///< n
  int sections = 26;                ///< w
  double endoscope_radius = 0.004;  ///< m
  double spring_stiffness = 15.0;   ///< N/m per wall spring
  double friction = 0.3;            ///< Coulomb μ
  double viscous_friction = 2.0;    ///< N·s/m
  double break_force = 4.0;         ///< N
  double break_torque = 0.08;       ///< N·m

  bool operator==(const UrethraLatticeSpec&) const = default;
};

/// A distribution attached to a template parameter (variability rules).
struct VariabilityRule {
  std::string parameter;
  std::string
      distribution;  ///< "fixed" | "uniform" | "truncated-normal" | "choice" | "integer-range"
  nlohmann::json arguments = nlohmann::json::object();

  bool operator==(const VariabilityRule&) const = default;
};

/// Where a scenario came from, so any patient can be rebuilt.
struct Provenance {
  std::string template_name;
  std::string template_version;
  std::uint64_t seed = 0;
  nlohmann::json parameters = nlohmann::json::object();
  std::map<std::string, std::string> tool_versions;

  bool operator==(const Provenance&) const = default;
};

/// Free description of the scenario.
struct Metadata {
  std::string name;
  std::string description;
  std::string author;

  bool operator==(const Metadata&) const = default;
};

}  // namespace viscera::core
