#include "simulator/dynamics/simulation_error.h"

namespace viscera::sim {

core::Error simulation_error(const std::string& reason, const std::string& body,
                             const std::string& element, long long step, double time) {
  return core::Error("simulation became unstable: " + reason + " at step " + std::to_string(step) +
                         " (t = " + std::to_string(time) + " s)",
                     {"body " + body, "", element});
}

}  // namespace viscera::sim
