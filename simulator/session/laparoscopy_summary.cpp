#include "simulator/session/laparoscopy_summary.h"

#include "core/json_eigen.h"

namespace viscera::sim {

namespace {
constexpr double kMlPerM3 = 1e6;
}  // namespace

nlohmann::json laparoscopy_json(const LaparoscopySummary& s, double blood_loss) {
  nlohmann::json clips = nlohmann::json::array();
  int secure = 0;
  for (const ClipPlacement& c : s.clips) {
    secure += c.secure() ? 1 : 0;
    clips.push_back({{"time", c.time},
                     {"body", c.body},
                     {"position", c.position},
                     {"knots", c.nodes},
                     {"across_degrees", c.across_degrees},
                     {"closes_lumen", c.closes_lumen},
                     {"secure", c.secure()},
                     {"gap_placed", c.gap_placed},
                     {"gap", c.gap}});
  }
  nlohmann::json cuts = nlohmann::json::array();
  for (const TissueCut& c : s.cuts) {
    cuts.push_back({{"time", c.time},
                    {"tool", c.tool},
                    {"body", c.body},
                    {"position", c.position},
                    {"tets_traversed", c.tets_traversed},
                    {"links_removed", c.links_removed},
                    {"divided", c.separated()},
                    {"between_clips", c.between_clips},
                    {"seconds", c.seconds}});
  }
  nlohmann::json coagulated = nlohmann::json::array();
  double length = 0.0;
  for (const CoagulatedTissue& c : s.coagulated) {
    length += c.length;
    coagulated.push_back({{"body", c.body}, {"knots", c.nodes}, {"length", c.length}});
  }
  return {{"tool_switches", s.tool_switches},
          {"grasps", s.grasps},
          {"knots_torn_out", s.knots_torn_out},
          {"max_grasp_force", s.max_grasp_force},
          {"clips_placed", s.clips.size()},
          {"clips_secure", secure},
          {"clips", clips},
          {"cuts", cuts},
          {"coagulation_time", s.coagulation_time},
          {"smoke_time", s.smoke_time},
          {"peak_lens_fog", s.peak_lens_fog},
          {"smoke_puffs", s.smoke_puffs},
          {"smoke_puffs_suctioned", s.smoke_puffs_suctioned},
          {"irrigated_ml", s.irrigated_volume * kMlPerM3},
          {"suctioned_ml", s.suctioned_volume * kMlPerM3},
          {"pool_ml", s.pool_volume * kMlPerM3},
          {"pool_blood_fraction", s.pool_blood_fraction},
          {"coagulated_length", length},
          {"coagulated", coagulated},
          {"blood_loss", blood_loss},
          {"path_per_tool", s.path_per_tool},
          {"path_per_hand", s.path_per_hand}};
}

}  // namespace viscera::sim
