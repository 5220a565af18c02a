#pragma once
/// Chips taken out of the cavity through the cervix (issue 17 §3: excised chips "can be removed
/// through the sheath"). Seed 000 pushes the chips against the fundus (§7, Fig. 6–7) and leaves
/// their removal open; this is how a resectoscopist does it.
///
/// Decided where the seed is silent:
/// - The chip is caught between the loop and the sheath: the loop is stood out beyond
///   `catch_extension` and drawn back to within it with both pedals up (as the surgeon hooks a
///   chip; the strokes of a cut, drawn back with the cutting pedal down, catch nothing), and
///   the first chip (in LoopResection::chips() order) with a node within the loop's radius plus
///   `catch_reach` of the loop's centre is held — every node of it is tied to the loop frame by
///   springs (a GraspTerm): the loop clamps the chip against the sheath, so the chip moves whole
///   with the instrument and still meets the wall through body contact. (Holding only the nodes
///   within reach left the rest of a larger myoma chip dangling: drawn through the canal, it
///   stretched past the tearing threshold and tore again and again.)
/// - Extending the loop again or pressing a pedal lets go of it.
/// - It is retrieved when the tip is drawn back to where the session started it, 3 mm inside the
///   internal os (manual_control.h starting_pose): the sheath, the loop and the chip are then in
///   the cervical canal. The chip leaves its body (LoopResection::retrieve); its volume stays
///   resected and the report counts it retrieved. The chips still in the cavity at the end are
///   in the report as `chips` per pathology.

#include <vector>

#include "simulator/dynamics/grasp_term.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/loop_resection.h"
#include "simulator/world/world.h"

namespace viscera::sim {

struct ChipRetrievalSettings {
  double catch_extension = 0.003;  ///< m: loop travel in front of the sheath that holds a chip
  double catch_reach = 0.001;      ///< m beyond the loop's radius around its centre
  double hold_stiffness = 30.0;    ///< N/m per held node (as the grasper's jaws)
};

class ChipRetrieval {
 public:
  /// Adds the loop's hold to `world`. `entry`: the instrument's starting pose (its tip 3 mm
  /// inside the internal os, its axis into the cavity).
  ChipRetrieval(World& world, const InstrumentState& entry, ChipRetrievalSettings settings = {});

  /// After every physics step (after LoopResection::follow): catches, carries, lets go of or
  /// retrieves a chip of `resection` with the instrument at `state`, at `time` s.
  void follow(const InstrumentState& state, World& world, LoopResection& resection, double time,
              CuttingSummary& summary, std::vector<SessionEvent>& events);

  /// True while a chip is held between the loop and the sheath.
  bool holding() const { return hold_->holding(); }

 private:
  /// Holds the first chip within the loop's reach; false when none is.
  bool try_catch(const InstrumentState& state, World& world, const LoopResection& resection,
                 double time, std::vector<SessionEvent>& events);
  /// The index in resection.chips() of the chip held, or −1.
  int held_chip(const LoopResection& resection) const;

  ChipRetrievalSettings settings_;
  GraspTerm* hold_ = nullptr;  ///< owned by the world
  core::Vec3 entry_tip_;
  core::Vec3 entry_axis_;
  /// The loop stood out with the pedals up since the last pedal press: drawing it back now
  /// catches a chip.
  bool armed_ = false;
};

}  // namespace viscera::sim
