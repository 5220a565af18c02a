#pragma once
/// A tip that follows the tissue (InstrumentState::follow): a trainee keeps the tool on what he
/// sees, so a scripted place on a landmark moves with the tissue around it — the wall a
/// distended cavity pushes back by about a millimetre, and the polyp stalk on it.

#include <span>

#include "simulator/session/instrument_state.h"
#include "simulator/world/body_view.h"

namespace viscera::sim {

/// Mean displacement (current − rest position, m) of the `count` nodes of `body` whose rest
/// positions lie nearest `anchor` (m; ties broken by the lower node); zero for an empty body.
core::Vec3 displacement_near(const BodyView& body, const core::Vec3& anchor, int count = 4);

/// `input` with its tip moved by input.follow × displacement_near(body, input.anchor), body the
/// one of `bodies` named input.anchor_body, or `instrument_body` when that is empty; the input
/// itself when it does not follow or there is no such body.
InstrumentState followed(const InstrumentState& input, std::span<const BodyView> bodies,
                         const BodyView* instrument_body);

}  // namespace viscera::sim
