#pragma once
/// What the laparoscopic tools did in a session (issue 19 §3, §6): grasps, clips, scissor cuts,
/// coagulated tissue and the tip's path with each tool. Absent from the report when the
/// session's instrument carries no laparoscopic tools.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// One clip fired by the clip applier.
struct ClipPlacement {
  double time = 0.0;                              ///< s
  std::string body;                               ///< the object it closed on
  core::Vec3 position = core::Vec3::Zero();       ///< m, centroid of its nodes when placed
  core::Vec3 rest_position = core::Vec3::Zero();  ///< m, the same in the rest configuration
  int nodes = 0;                                  ///< knots between its jaws
  /// Angle between the tube's local axis and the clip's jaws, degrees: 90 straight across.
  double across_degrees = 0.0;
  /// Knots on both sides of the lumen were caught, so closing the jaws closes it.
  bool closes_lumen = false;
  double gap_placed = 0.0;  ///< m, extent of its knots along the closing direction when placed
  double gap = 0.0;         ///< m, the same now (the squeezed lumen)
  /// Across (≥ 60°) and closing the lumen: a clip that occludes the tube.
  bool secure() const { return closes_lumen && across_degrees >= 60.0; }
};

/// One closing of the scissors on tissue.
/// A cut by the scissors (closing blades) or the hook (cutting current along its sweep).
struct TissueCut {
  double time = 0.0;  ///< s
  std::string tool;   ///< "scissors" or "hook"
  std::string body;
  /// m, centre of the tissue between the blades, or of the hook's sweep
  core::Vec3 position = core::Vec3::Zero();
  int pieces_before = 1, pieces_after = 1;  ///< connected components of the body
  int tets_traversed = 0;
  int links_removed = 0;  ///< of a cell-agent tissue (seed 003 §V), which has no tets
  /// The cut lies between two secure clips on the same body (along the line joining them).
  bool between_clips = false;
  double seconds = 0.0;  ///< wall time of the cut (the run, not the state)
  bool separated() const { return pieces_after > pieces_before; }
};

/// Tissue of one body coagulated by the bipolar forceps.
struct CoagulatedTissue {
  std::string body;
  int nodes = 0;
  /// m, per site the extent of the coagulated knots along the body's local axis (principal
  /// direction of its rest knots within 1 cm) plus the jaws' width, summed over sites (knots
  /// more than 5 mm from every other coagulated knot start a new site).
  double length = 0.0;
  std::vector<core::Vec3> rest_positions;  ///< m, the coagulated knots at rest
};

struct LaparoscopySummary {
  int tool_switches = 0;
  int grasps = 0;                 ///< closings of the grasper that held tissue
  int knots_torn_out = 0;         ///< held knots that tore out of the jaws
  double max_grasp_force = 0.0;   ///< N, the tissue's largest pull on the jaws
  double coagulation_time = 0.0;  ///< s of coagulating current through tissue (bipolar, hook)
  double smoke_time = 0.0;        ///< s with the field visibly smoky (SurgicalSmoke)
  double peak_lens_fog = 0.0;     ///< 0…1, the most the lens steamed up
  int smoke_puffs = 0;
  int smoke_puffs_suctioned = 0;  ///< puffs the suction cannula drew off
  /// The suction–irrigation cannula and the pool (suction_irrigation.h), m³: fluid the jet
  /// delivered, fluid (water and blood) the suction drew off the pool, what the pool holds now
  /// and its blood over all its fluid (0…1).
  double irrigated_volume = 0.0;
  double suctioned_volume = 0.0;
  double pool_volume = 0.0;
  double pool_blood_fraction = 0.0;
  std::vector<ClipPlacement> clips;
  std::vector<TissueCut> cuts;
  std::vector<CoagulatedTissue> coagulated;
  std::map<std::string, double> path_per_tool;  ///< m of tip travel with each tool in a port
  /// m of tip travel per hand: "right" (the laparoscope's working port) and, once a tool was in
  /// the second port, "left".
  std::map<std::string, double> path_per_hand;

  const CoagulatedTissue* coagulated_of(const std::string& body) const {
    for (const auto& c : coagulated)
      if (c.body == body) return &c;
    return nullptr;
  }
};

/// The summary as JSON, with `blood_loss` m³ (the report's bleeding sources) among the
/// metrics of issue 19 §6: clips placed and secure, coagulated length (m), coagulation time (s),
/// tool path per tool and per hand (m), and the irrigation, suction and pool volumes in ml (the
/// unit on the operating room's fluid chart; their names end in "_ml"). Positions in m, times in s,
/// forces in N.
nlohmann::json laparoscopy_json(const LaparoscopySummary& summary, double blood_loss);

}  // namespace viscera::sim
