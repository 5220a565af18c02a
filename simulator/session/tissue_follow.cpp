#include "simulator/session/tissue_follow.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace viscera::sim {

core::Vec3 displacement_near(const BodyView& body, const core::Vec3& anchor, int count) {
  const auto rest = body.rest_positions();
  const auto current = body.positions();
  constexpr int kMost = 8;
  count = std::clamp(count, 1, kMost);
  // The nearest `count` nodes, kept sorted by (distance², node): one pass, no allocation.
  std::array<std::pair<double, std::size_t>, kMost> nearest;
  nearest.fill({std::numeric_limits<double>::infinity(), 0});
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const std::pair<double, std::size_t> candidate{(rest[i] - anchor).squaredNorm(), i};
    if (!(candidate < nearest[static_cast<std::size_t>(count - 1)])) continue;
    auto at = static_cast<std::size_t>(count - 1);
    for (; at > 0 && candidate < nearest[at - 1]; --at)
      nearest[at] = nearest[at - 1];
    nearest[at] = candidate;
  }
  const auto found = static_cast<int>(std::min<std::size_t>(rest.size(), count));
  core::Vec3 sum = core::Vec3::Zero();
  for (int k = 0; k < found; ++k) {
    const std::size_t i = nearest[static_cast<std::size_t>(k)].second;
    sum += current[i] - rest[i];
  }
  return found > 0 ? core::Vec3(sum / found) : core::Vec3::Zero();
}

InstrumentState followed(const InstrumentState& input, std::span<const BodyView> bodies,
                         const BodyView* instrument_body) {
  if (!(input.follow > 0.0)) return input;
  const BodyView* body = instrument_body;
  if (!input.anchor_body.empty()) {
    const auto named = std::find_if(bodies.begin(), bodies.end(), [&](const BodyView& b) {
      return b.name() == input.anchor_body;
    });
    body = named != bodies.end() ? &*named : nullptr;
  }
  if (body == nullptr) return input;
  InstrumentState out = input;
  out.tip += input.follow * displacement_near(*body, input.anchor);
  return out;
}

}  // namespace viscera::sim
