#pragma once
/// The laparoscopic tools of the working port in a session (seed 001 §4.1; issue 19 §3): a
/// grasper, a clip applier, scissors and bipolar forceps, switched during the session
/// (InstrumentState::tool) and worked by closing their jaws (InstrumentState::jaws_closed).
///
/// Every tool has jaws at the instrument's tip: they reach `jaw_length` m back along the shaft
/// from the tip, open `jaw_opening` m along InstrumentState::up, and are `jaw_width` m wide
/// across (along axis × up). The tissue between the jaws is the free knots of the body nearest
/// the tip inside that box; where the body's knots are coarser than the jaws are wide (the
/// laparoscopy nets space their knot rings a few mm apart), the knot ring nearest the jaws'
/// mid-plane is taken instead, so the jaws never close on nothing that lies between them.
///
/// - Grasper: closing takes the tissue between the jaws (GraspTerm); it follows the jaws while
///   they stay closed and pulls back on the hand; a knot pulled harder than `grasp_slip_force`
///   tears out of the jaws. Opening releases.
/// - Clip applier: each closing on tissue fires one clip (ClipTerm) squeezing its knots flat
///   along the jaws' closing direction; clips stay to the end of the session.
/// - Scissors: each closing cuts the tissue between the blades along the triangle the blades
///   sweep (hinge `jaw_length` behind the tip, blade tips `scissor_spread` either side of it)
///   (cutting::scissor_cut_surface, then the hybrid cut of seed 000 §5.1 and
///   World::topology_changed).
/// - Suction cannula: while its valve is open (the jaws "closed") it draws off the smoke within
///   `suction_reach` m of its tip (seed 001 §4.3: suction "removes" smoke). It is a suction–
///   irrigation cannula: its irrigation jet and the pool its suction also draws off are
///   SuctionIrrigation's (suction_irrigation.h), which the session runs beside the tools.
/// - Hook: a monopolar L-hook (electrosurgical_hook.h). With the cutting pedal down its wire's
///   sweep is recorded and, when the current stops, cut through every body it crosses (the
///   hybrid cut, as the scissors); with the coagulation pedal down it heats the knots its wire
///   touches as the bipolar forceps heat those between their jaws. It touches tissue with its
///   bend, or under cutting current with the shaft behind the bare wire (hook_touch_point).
/// - Every tool: coagulation raises smoke from the tissue between the jaws and steams the lens
///   at the instrument's tip (SurgicalSmoke).
/// - Bipolar forceps: with the jaws closed and the coagulation pedal down, the knots between
///   the jaws heat; a knot that has had `coagulation_dose` s of current is coagulated: the
///   springs between coagulated knots stiffen by `coagulated_stiffening` and shorten by
///   `coagulated_shrinkage` (desiccated tissue is stiffer and contracts), and the session seals
///   bleeding and stops pulse waves there (observers). The coagulated length of a site is the
///   extent of its knots along the tube plus one jaw width (the burn under the jaws).
///
/// The instrument touches tissue with the jaws' hinge (hinge(): `jaw_length` behind the tip):
/// open jaws straddle what they are to close on, so the haptic proxy sits where the jaws meet.
///
/// Decisions where the seeds are silent are the defaults of LaparoscopicToolOptions, stated
/// with their reasons there.

#include <array>
#include <functional>
#include <span>
#include <vector>

#include "simulator/cutting/topology_change.h"
#include "simulator/dynamics/clip_term.h"
#include "simulator/dynamics/grasp_term.h"
#include "simulator/session/electrosurgical_hook.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/laparoscopy_summary.h"
#include "simulator/session/session_report.h"
#include "simulator/session/surgical_smoke.h"
#include "simulator/session/visible_surfaces.h"
#include "simulator/world/world.h"

namespace viscera::sim {

class AgentTissueTerm;

struct LaparoscopicToolOptions {
  double jaw_length = 0.012;   ///< m: 5 mm laparoscopic instruments have 10–20 mm jaws
  double jaw_opening = 0.008;  ///< m: wide enough for a tube or vessel of up to 8 mm
  double jaw_width = 0.003;    ///< m, across the jaws
  double clip_width = 0.0015;  ///< m, a titanium clip's leg
  /// m from the tip to each open scissor blade's tip, across the shaft: with the jaw length a
  /// 45° half-angle, so a tube sitting mid-way into the blades is crossed whole.
  double scissor_spread = 0.012;
  /// m either side of the jaws' mid-plane searched for the nearest knot ring when none lies
  /// within the jaws' width.
  double ring_search = 0.004;
  double grasp_stiffness = 30.0;  ///< N/m per held knot
  double grasp_slip_force = 1.0;  ///< N per held knot before it tears out of the jaws
  double clip_stiffness = 60.0;   ///< N/m per clipped knot
  /// m between a closed clip's jaws: the two crushed walls of a tube or vessel.
  double clip_closed_gap = 0.001;
  double clip_closing_time = 0.3;      ///< s the applier's jaws take to close a clip
  double suction_reach = 0.015;        ///< m around the suction cannula's tip
  double coagulation_dose = 1.0;       ///< s of bipolar current that coagulates a knot
  double coagulated_stiffening = 2.0;  ///< factor on the springs between coagulated knots
  double coagulated_shrinkage = 0.05;  ///< fraction their rest length shortens
  HookOptions hook;                    ///< the monopolar L-hook's wire and sweep
};

class LaparoscopicTools {
 public:
  /// The tools act on every body of `world` with tets (KisMo nets and Teschner bodies); the
  /// grasper's term is added to the world.
  LaparoscopicTools(World& world, LaparoscopicToolOptions options = {});

  /// After every physics step of `dt` s with the instruments in `state` (the working port and,
  /// when a tool is in it, the second port: in_port): switches tools, opens and closes jaws,
  /// moves what each grasper holds, heats tissue; records in `summary` and `events` at `time`
  /// s. The lens the smoke steams is the laparoscope's (camera_pose).
  void follow(const InstrumentState& state, World& world, double time, double dt,
              LaparoscopySummary& summary, std::vector<SessionEvent>& events);

  /// Force of the held tissue on the jaws of port `port`'s grasper, N (zero when it holds
  /// nothing).
  core::Vec3 force(const World& world, int port = 0) const;
  /// The grasper of port `port` (0: the working port, 1: the second port).
  const GraspTerm& grasp(int port = 0) const {
    return *ports_[static_cast<std::size_t>(port)].grasp;
  }
  /// The clips placed so far, in order.
  const std::vector<ClipTerm*>& clips() const { return clips_; }
  /// Per world body and node: 1 for a coagulated knot.
  const std::vector<std::vector<std::uint8_t>>& coagulated() const { return coagulated_; }
  const LaparoscopicToolOptions& options() const { return options_; }
  /// The world bodies with tets the tools act on (the cell-agent tissues they also grasp and
  /// cut are not among them: they have no tets to cut or tear).
  const std::vector<int>& bodies() const { return bodies_; }
  /// The largest strain (length over rest length − 1) of the links — a net's springs, a cell
  /// tissue's connections — at the knots either grasper holds; 0 when they hold none.
  double grasp_stretch(const World& world) const;
  /// The smoke of coagulation and the fog on the lens (the laparoscope's, camera_pose).
  const SurgicalSmoke& smoke() const { return smoke_; }

  /// Told of a clip placed on body `body` (its world index) at `time` s.
  using ClipObserver = std::function<void(int body, const ClipTerm& clip, double time)>;
  void on_clip(ClipObserver observer) { clip_observer_ = std::move(observer); }
  /// Told of knots of `body` coagulated at `time` s (body-local indices).
  using CoagulationObserver =
      std::function<void(int body, const std::vector<int>& nodes, double time)>;
  void on_coagulation(CoagulationObserver observer) { coagulation_observer_ = std::move(observer); }
  /// Told of a scissor cut of `body` after the world took its new topology.
  using CutObserver =
      std::function<void(int body, const cutting::TopologyChange& change, double time)>;
  void on_cut(CutObserver observer) { cut_observer_ = std::move(observer); }
  /// Cuts go through `surfaces` (null: the tets alone), so the bodies' visible surfaces follow.
  void cut_visible_surfaces(VisibleSurfaces* surfaces) { visible_ = surfaces; }

  /// The knots between the jaws at `state`: body-local nodes of one body (empty when none).
  std::vector<NodeReference> tissue_between_jaws(const World& world, const InstrumentState& state,
                                                 double width) const;
  /// The knots within the hook's coagulation reach of its wire at `state`: nodes of the one
  /// body the wire touches most closely (empty when none is within reach).
  std::vector<NodeReference> tissue_at_hook(const World& world, const InstrumentState& state) const;

 private:
  /// One port's tool and what it keeps from step to step.
  struct Port {
    explicit Port(const HookOptions& hook_options) : hook(hook_options) {}
    InstrumentState previous;
    bool first = true;  ///< no step seen with a tool in the port yet
    GraspTerm* grasp = nullptr;
    HookSweep hook;
  };
  /// follow() for one port's tool in `state`; `hand` names it in the path per hand.
  void follow_port(Port& port, const InstrumentState& state, const char* hand, World& world,
                   double time, double dt, LaparoscopySummary& summary,
                   std::vector<SessionEvent>& events);
  /// The port's tool left the abdomen: what it held is let go.
  void withdraw(Port& port, World& world, double time, std::vector<SessionEvent>& events);
  void close_jaws(Port& port, const InstrumentState& state, World& world, double time,
                  LaparoscopySummary& summary, std::vector<SessionEvent>& events);
  void place_clip(const InstrumentState& state, World& world, double time,
                  LaparoscopySummary& summary, std::vector<SessionEvent>& events);
  void cut(const InstrumentState& state, World& world, double time, LaparoscopySummary& summary,
           std::vector<SessionEvent>& events);
  void cut_with_hook(const cutting::CutSurface& sweep, World& world, double time,
                     LaparoscopySummary& summary, std::vector<SessionEvent>& events);
  /// Cuts `body` along `surface` by `tool` ("scissors", "hook") and records the cut: false when
  /// the surface crosses none of its tets.
  bool cut_through(int body, const cutting::CutSurface& surface, const core::Vec3& centre,
                   const char* tool, World& world, double time, LaparoscopySummary& summary,
                   std::vector<SessionEvent>& events);
  /// The cell-agent term of world body `body`, or null.
  AgentTissueTerm* agents_of(int body) const;
  /// Cuts the links of a cell-agent tissue that cross `triangles` (seed 003 §V: cutting removes
  /// neighbour links) and records the cut: false when none crosses.
  bool cut_links(AgentTissueTerm& agents, std::span<const std::array<core::Vec3, 3>> triangles,
                 const char* tool, World& world, double time, LaparoscopySummary& summary,
                 std::vector<SessionEvent>& events);
  /// Heats `between` (nodes of one body) for `dt` s: coagulates the knots that had their dose.
  void heat(const std::vector<NodeReference>& between, World& world, double time, double dt,
            LaparoscopySummary& summary, std::vector<SessionEvent>& events);
  /// Stiffens and shortens the springs whose both knots are coagulated (after any change of
  /// the set or of the body's topology).
  void stiffen_coagulated(World& world, int body);
  void refresh_clips(const World& world, LaparoscopySummary& summary) const;
  /// grasp_stretch at the knots `grasp` holds (it holds some).
  double grasp_stretch(const World& world, const GraspTerm& grasp) const;

  LaparoscopicToolOptions options_;
  std::vector<int> bodies_;               ///< world bodies with tets the tools act on
  std::vector<AgentTissueTerm*> agents_;  ///< the cell-agent tissues, grasped and cut by links
  std::vector<int> touchable_;            ///< bodies_ and the agents' bodies
  std::vector<Port> ports_;               ///< kInstrumentPorts: the working port, the second port
  std::vector<ClipTerm*> clips_;
  std::vector<int> clip_bodies_;
  std::vector<std::vector<double>> dose_;  ///< per body and node, s of current
  std::vector<std::vector<std::uint8_t>> coagulated_;
  /// Per body, per spring of its KisMo term: 1 once stiffened (reset when a cut rebuilds it).
  std::vector<std::vector<std::uint8_t>> stiffened_;
  SurgicalSmoke smoke_;
  std::optional<core::Vec3> coagulating_at_;  ///< m, where current flowed this step
  ClipObserver clip_observer_;
  CoagulationObserver coagulation_observer_;
  CutObserver cut_observer_;
  VisibleSurfaces* visible_ = nullptr;
};

/// Where a tool with jaws touches tissue: the hinge, `jaw_length` m behind the tip along the
/// shaft (the tip itself for LaparoscopicTool::None).
core::Vec3 hinge(const InstrumentState& state, const LaparoscopicToolOptions& options);

/// The jaw frame at `state`: columns across the jaws (axis × up), up (the closing direction)
/// and the shaft axis.
core::Mat3 jaw_frame(const InstrumentState& state);

/// Coagulated length of `body` from its coagulated knots at rest (m): per site (knots within
/// 5 mm of one another) their extent along the body's local axis plus `jaw_width`, summed.
double coagulated_length(const World& world, int body, const std::vector<core::Vec3>& rest,
                         double jaw_width);

/// Unit principal direction of the rest knots of `body` within `radius` m of `point` (the
/// local axis of a tube), or zero when fewer than two lie there.
core::Vec3 local_axis(const World& world, int body, const core::Vec3& point, double radius);

}  // namespace viscera::sim
