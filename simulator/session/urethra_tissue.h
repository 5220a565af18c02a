#pragma once
/// The instrument in the urethra lattice of the NTUA urological trainer (seed 002 §3, §5): each
/// physics step the instrument pose becomes an EndoscopeState — pitch θx and yaw θy from the
/// shaft axis, the tip's velocity from its displacement over the step, the spin rate from the
/// roll of the up vector about the axis — and the UrethraModel's feedback gives the force on the
/// endoscope (eq. 6–8), the torques (eq. 9–13), the warnings near the tissue-break limits and
/// the tear when a limit is exceeded.

#include <set>

#include "core/scenario/scenario_parts.h"
#include "simulator/physics/urethra_model.h"
#include "simulator/session/instrument_tissue.h"

namespace viscera::sim {

/// Model parameters from a package's urethra lattice (the other constants keep the seed-002
/// defaults of UrethraParameters).
UrethraParameters urethra_parameters(const core::UrethraLatticeSpec& spec);

/// The urethra lattice under the endoscope.
class UrethraTissue final : public InstrumentTissue {
 public:
  /// The endoscope starts at rest in `start`.
  UrethraTissue(const core::UrethraLatticeSpec& spec, const InstrumentState& start);

  const std::string& name() const override { return name_; }
  void move(const InstrumentState& state, double dt) override;
  core::Vec3 force() const override { return feedback_.force; }
  /// The wall springs press on the shaft (normal force > 0): the endoscope, wider than the
  /// lumen, is inside.
  bool in_contact() const override { return feedback_.normal_force > 0.0; }
  /// "perforation" when the axial force exceeds the break force, "tissue-tear" when a torque
  /// exceeds the break torque.
  std::optional<TissueEvent> complication() override;
  /// The model's warnings ("… near the tissue-break limit") that began at this step.
  std::vector<TissueEvent> warnings() override;
  std::string state_hash() const override;

  const UrethraModel& model() const { return model_; }
  const EndoscopeState& endoscope() const { return endoscope_; }
  const UrethraFeedback& feedback() const { return feedback_; }

 private:
  std::string name_;
  UrethraModel model_;
  InstrumentState last_;
  EndoscopeState endoscope_;
  UrethraFeedback feedback_;
  std::set<std::string> active_warnings_;
};

}  // namespace viscera::sim
