#include "simulator/fluid/distension_balance.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace viscera::sim {

namespace {

void require_pressure(double value, const char* member) {
  if (!std::isfinite(value) || value < 0.0)
    throw core::InputError("/scenario/fluid/" + std::string(member) + " is " +
                           std::to_string(value) + " Pa; it must be a finite pressure ≥ 0");
}

void require_positive(double value, const char* what) {
  if (!std::isfinite(value) || value <= 0.0)
    throw core::InputError(std::string("distension channel constant ") + what + " is " +
                           std::to_string(value) + "; it must be positive");
}

}  // namespace

double DistensionChannels::poiseuille_conductance(double radius, double length, double viscosity) {
  return std::numbers::pi * std::pow(radius, 4) / (8.0 * viscosity * length);
}

DistensionBalance::DistensionBalance(const core::FluidSpec& fluid, DistensionChannels channels)
    : fluid_(fluid), channels_(channels) {
  require_pressure(fluid.inflow_pressure, "inflow_pressure");
  require_pressure(fluid.outflow_pressure, "outflow_pressure");
  if (!std::isfinite(fluid.overload_volume) || fluid.overload_volume <= 0.0)
    throw core::InputError("/scenario/fluid/overload_volume is " +
                           std::to_string(fluid.overload_volume) + " m³; it must be positive");
  require_positive(channels.inflow_conductance, "inflow_conductance");
  require_positive(channels.outflow_conductance, "outflow_conductance");
  require_positive(channels.cavity_compliance, "cavity_compliance");
  require_positive(channels.absorption_conductance, "absorption_conductance");
  require_pressure(channels.absorption_threshold, "absorption_threshold");
  if (!std::isfinite(channels.resting_volume) || channels.resting_volume < 0.0)
    throw core::InputError("distension channel constant resting_volume must be ≥ 0");
}

double DistensionBalance::cavity_volume() const {
  return channels_.resting_volume + channels_.cavity_compliance * pressure_;
}

double DistensionBalance::advance_regime(double g_in, double g_out, bool absorbing, double dt) {
  const double g_abs = absorbing ? channels_.absorption_conductance : 0.0;
  const double threshold = channels_.absorption_threshold;
  const double b = g_in + g_out + g_abs;
  if (b <= 0.0 || dt <= 0.0) return pressure_;  // sealed cavity: nothing flows
  const double a =
      g_in * fluid_.inflow_pressure + g_out * fluid_.outflow_pressure + g_abs * threshold;
  const double target = a / b;
  const double rate = b / channels_.cavity_compliance;  // 1/s
  const double decay = std::exp(-rate * dt);
  const double end = target + (pressure_ - target) * decay;
  // ∫P dt over the step, exactly: P* t + (P₀ − P*)(1 − e^{−kt})/k.
  const double pressure_time =
      target * dt + (pressure_ - target) * (-std::expm1(-rate * dt)) / rate;
  totals_.used += g_in * (fluid_.inflow_pressure * dt - pressure_time);
  totals_.drained += g_out * (pressure_time - fluid_.outflow_pressure * dt);
  if (absorbing) {
    totals_.absorbed += g_abs * (pressure_time - threshold * dt);
    totals_.time_above_threshold += dt;
  }
  totals_.max_pressure = std::max({totals_.max_pressure, pressure_, end});
  return end;
}

void DistensionBalance::step(double inflow_opening, double outflow_opening, double dt) {
  if (!(dt > 0.0)) return;
  const double g_in = std::clamp(inflow_opening, 0.0, 1.0) * channels_.inflow_conductance;
  const double g_out = std::clamp(outflow_opening, 0.0, 1.0) * channels_.outflow_conductance;
  const double threshold = channels_.absorption_threshold;
  const double compliance = channels_.cavity_compliance;

  // The regime at the start, and where its exponential heads.
  const bool absorbing = pressure_ > threshold;
  const double g_abs = absorbing ? channels_.absorption_conductance : 0.0;
  const double b = g_in + g_out + g_abs;
  double crossing = dt;  // s until P reaches the threshold, if it does within the step
  if (b > 0.0) {
    const double target =
        (g_in * fluid_.inflow_pressure + g_out * fluid_.outflow_pressure + g_abs * threshold) / b;
    const bool heads_across = absorbing ? target < threshold : target > threshold;
    if (heads_across && pressure_ != target) {
      // P(t) = P* + (P₀ − P*) e^{−kt} = threshold  ⇒  t = ln((P₀ − P*)/(threshold − P*)) / k.
      const double t = std::log((pressure_ - target) / (threshold - target)) * compliance / b;
      if (t < dt) crossing = std::max(t, 0.0);
    }
  }
  const double end = advance_regime(g_in, g_out, absorbing, crossing);
  if (crossing < dt) {
    pressure_ = threshold;  // exactly on the regime boundary
    pressure_ = advance_regime(g_in, g_out, !absorbing, dt - crossing);
  } else {
    pressure_ = end;
  }
}

}  // namespace viscera::sim
