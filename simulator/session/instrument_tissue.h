#pragma once
/// The tissue the instrument of a session acts on (DESIGN.md §5): a deformable body of the World
/// pressed through a proxy spring, or the urethra lattice of seed 002 with its force model. The
/// SessionRunner moves the instrument, reads the force and contact for the metrics, and ends the
/// session on a complication the tissue reports.

#include <optional>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "simulator/session/instrument_state.h"

namespace viscera::sim {

class BodyView;

/// A complication or a warning raised by the tissue: the event kind and one sentence.
struct TissueEvent {
  std::string kind;  ///< e.g. "perforation", "tissue-tear", "force-warning"
  std::string message;
};

/// The tissue under the instrument.
class InstrumentTissue {
 public:
  virtual ~InstrumentTissue() = default;
  /// Id of the scenario object the instrument acts on.
  virtual const std::string& name() const = 0;
  /// The instrument moves to `state` for the next physics step of `dt` s (before the world
  /// steps).
  virtual void move(const InstrumentState& state, double dt) = 0;
  /// Force of the tissue on the instrument after the step, N.
  virtual core::Vec3 force() const = 0;
  /// True while the tissue presses on the instrument.
  virtual bool in_contact() const = 0;
  /// The complication that ends the session after this step (perforation, tear), if any.
  virtual std::optional<TissueEvent> complication() = 0;
  /// Warnings that began at this step (each once per episode).
  virtual std::vector<TissueEvent> warnings() = 0;
  /// Hex hash of the tissue's own state beyond the World's (empty when the World holds it all).
  virtual std::string state_hash() const = 0;
  /// The deformable body the camera observes, or null when the tissue is not a World body.
  virtual const BodyView* body() const { return nullptr; }
};

}  // namespace viscera::sim
