#include "simulator/fluid/distension_balance.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

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

/// C dP/dt = a − b·P: the valves, the absorption when it is in force, and every opening.
struct DistensionBalance::Regime {
  double g_in = 0.0, g_out = 0.0, g_abs = 0.0;
  double a = 0.0;  ///< m³ s⁻¹
  double b = 0.0;  ///< m³ s⁻¹ Pa⁻¹
  double target() const { return a / b; }
};

DistensionBalance::Regime DistensionBalance::regime(double g_in, double g_out) const {
  Regime r{g_in, g_out, 0.0, g_in * fluid_.inflow_pressure + g_out * fluid_.outflow_pressure,
           g_in + g_out};
  for (const VesselOpening& opening : openings_) {
    r.a += opening.conductance * opening.pressure;
    r.b += opening.conductance;
  }
  // Absorbing above the threshold, and on it when the pressure heads up (the absorbing regime's
  // target then lies above the threshold too, so the regime does not flip back).
  const double threshold = channels_.absorption_threshold;
  const bool absorbing =
      pressure_ > threshold || (pressure_ == threshold && r.b > 0.0 && r.target() > threshold);
  if (absorbing) {
    r.g_abs = channels_.absorption_conductance;
    r.a += r.g_abs * threshold;
    r.b += r.g_abs;
  }
  return r;
}

void DistensionBalance::advance(const Regime& r, double dt) {
  const double target = r.target();
  const double rate = r.b / channels_.cavity_compliance;  // 1/s
  const double end = target + (pressure_ - target) * std::exp(-rate * dt);
  // ∫P dt over the piece, exactly: P* t + (P₀ − P*)(1 − e^{−kt})/k.
  const double pressure_time =
      target * dt + (pressure_ - target) * (-std::expm1(-rate * dt)) / rate;
  totals_.used += r.g_in * (fluid_.inflow_pressure * dt - pressure_time);
  totals_.drained += r.g_out * (pressure_time - fluid_.outflow_pressure * dt);
  if (r.g_abs > 0.0) {
    totals_.absorbed += r.g_abs * (pressure_time - channels_.absorption_threshold * dt);
    totals_.time_above_threshold += dt;
  }
  // No opening's pressure lies strictly inside the piece, so each flow keeps its sign.
  for (std::size_t j = 0; j < openings_.size(); ++j) {
    const double volume = openings_[j].conductance * (openings_[j].pressure * dt - pressure_time);
    (volume >= 0.0 ? totals_.bled : totals_.intravasated) += std::abs(volume);
    last_step_volumes_[j] += volume;
  }
  totals_.max_pressure = std::max({totals_.max_pressure, pressure_, end});
  totals_.pressure_time += pressure_time;
  totals_.duration += dt;
  pressure_ = end;
}

void DistensionBalance::step(double inflow_opening, double outflow_opening, double dt) {
  last_step_volumes_.assign(openings_.size(), 0.0);
  if (!(dt > 0.0)) return;
  const double g_in = std::clamp(inflow_opening, 0.0, 1.0) * channels_.inflow_conductance;
  const double g_out = std::clamp(outflow_opening, 0.0, 1.0) * channels_.outflow_conductance;

  // Within a regime P heads monotonically for its target, so the step splits at most once per
  // kink (the absorption threshold, each opening's pressure) it crosses.
  double left = dt;
  for (std::size_t piece = 0; piece < openings_.size() + 2 && left > 0.0; ++piece) {
    const Regime r = regime(g_in, g_out);
    if (r.b <= 0.0) {  // sealed cavity: nothing flows, the pressure holds
      totals_.pressure_time += pressure_ * left;
      totals_.duration += left;
      return;
    }
    const double target = r.target();
    double duration = left;
    double kink_reached = pressure_;
    auto consider = [&](double kink) {
      const bool between =
          (pressure_ < kink && kink < target) || (target < kink && kink < pressure_);
      if (!between) return;
      // P(t) = P* + (P₀ − P*) e^{−kt} = kink  ⇒  t = ln((P₀ − P*)/(kink − P*)) / k.
      const double t =
          std::log((pressure_ - target) / (kink - target)) * channels_.cavity_compliance / r.b;
      if (t < duration) {
        duration = std::max(t, 0.0);
        kink_reached = kink;
      }
    };
    consider(channels_.absorption_threshold);
    for (const VesselOpening& opening : openings_)
      consider(opening.pressure);
    const bool splits = duration < left;
    advance(r, duration);
    if (splits) pressure_ = kink_reached;  // exactly on the kink, not a rounding short of it
    left -= duration;
  }
  // Every kink is crossed at most once, so the pieces above use up the step; should rounding
  // leave a remainder, it runs without a split.
  if (left > 0.0) {
    const Regime r = regime(g_in, g_out);
    if (r.b > 0.0) advance(r, left);
  }
}

void DistensionBalance::set_openings(std::vector<VesselOpening> openings) {
  for (const VesselOpening& opening : openings) {
    if (!std::isfinite(opening.conductance) || opening.conductance < 0.0 ||
        !std::isfinite(opening.pressure) || opening.pressure < 0.0)
      throw core::UsageError("a vessel opening needs a finite conductance ≥ 0 and pressure ≥ 0");
  }
  openings_ = std::move(openings);
  last_step_volumes_.assign(openings_.size(), 0.0);
}

}  // namespace viscera::sim
