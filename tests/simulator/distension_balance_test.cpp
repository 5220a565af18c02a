#include "simulator/fluid/distension_balance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/error.h"

namespace viscera::sim {
namespace {

core::FluidSpec saline() {
  core::FluidSpec fluid;
  fluid.enabled = true;
  fluid.inflow_pressure = 13332.0;  // 100 mmHg
  fluid.outflow_pressure = 0.0;
  fluid.overload_volume = 1.0e-3;
  return fluid;
}

/// The fluid that went in and did not come out: stored in the cavity above its resting volume
/// or absorbed. Exact for any step, so any drift is a defect of step().
double balance_error(const DistensionBalance& cavity) {
  const FluidTotals& t = cavity.totals();
  return t.used + t.bled - t.drained - t.absorbed - t.intravasated -
         cavity.channels().cavity_compliance * cavity.pressure();
}

TEST(DistensionBalance, channel_conductance_is_hagen_poiseuille_and_gives_clinical_flow) {
  const double g = DistensionChannels::poiseuille_conductance(0.6e-3, 0.35, 0.7e-3);
  EXPECT_NEAR(g, std::numbers::pi * std::pow(0.6e-3, 4) / (8 * 0.7e-3 * 0.35), 1e-22);
  // Into an empty cavity at 100 mmHg: continuous-flow hysteroscopes deliver 100–400 ml/min.
  const double ml_per_min = g * 13332.0 * 1e6 * 60.0;
  EXPECT_GT(ml_per_min, 100.0);
  EXPECT_LT(ml_per_min, 400.0);
}

TEST(DistensionBalance, pressure_follows_the_analytic_exponential_with_both_valves_open) {
  DistensionBalance cavity(saline());
  const DistensionChannels& c = cavity.channels();
  const double b = c.inflow_conductance + c.outflow_conductance;
  const double steady = c.inflow_conductance * 13332.0 / b;
  ASSERT_LT(steady, c.absorption_threshold);  // this case stays below absorption
  for (int i = 0; i < 4; ++i)
    cavity.step(1.0, 1.0, 0.25);  // four large steps to t = 1 s
  const double expected = steady * (1.0 - std::exp(-b / c.cavity_compliance * 1.0));
  EXPECT_NEAR(cavity.pressure(), expected, 1e-9 * steady);
  EXPECT_EQ(cavity.totals().absorbed, 0.0);
  EXPECT_NEAR(balance_error(cavity), 0.0, 1e-18);
}

TEST(DistensionBalance, inflow_alone_settles_where_pump_and_absorption_balance) {
  DistensionBalance cavity(saline());
  for (int i = 0; i < 600; ++i)
    cavity.step(1.0, 0.0, 0.5);
  const DistensionChannels& c = cavity.channels();
  const double steady =
      (c.inflow_conductance * 13332.0 + c.absorption_conductance * c.absorption_threshold) /
      (c.inflow_conductance + c.absorption_conductance);
  EXPECT_NEAR(cavity.pressure(), steady, 1e-6);
  EXPECT_GT(cavity.totals().absorbed, 0.0);
  EXPECT_GT(cavity.totals().time_above_threshold, 290.0);
  EXPECT_NEAR(cavity.totals().max_pressure, steady, 1e-6);
}

TEST(DistensionBalance, result_does_not_depend_on_the_step_even_across_the_threshold) {
  DistensionBalance fine(saline()), coarse(saline());
  for (int i = 0; i < 20000; ++i)
    fine.step(1.0, 0.0, 1e-3);  // 20 s, crosses 75 mmHg
  for (int i = 0; i < 8; ++i)
    coarse.step(1.0, 0.0, 2.5);
  ASSERT_GT(fine.totals().absorbed, 0.0);
  EXPECT_NEAR(coarse.pressure(), fine.pressure(), 1e-7 * fine.pressure());
  EXPECT_NEAR(coarse.totals().used, fine.totals().used, 1e-9 * fine.totals().used);
  EXPECT_NEAR(coarse.totals().absorbed, fine.totals().absorbed, 1e-7 * fine.totals().absorbed);
  EXPECT_NEAR(coarse.totals().time_above_threshold, fine.totals().time_above_threshold, 2e-3);
}

TEST(DistensionBalance, volume_is_conserved_over_a_ten_minute_session_of_valve_changes) {
  DistensionBalance cavity(saline());
  std::uint64_t state = 12345;
  auto next = [&state] {  // LCG in [0, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  double inflow = 1.0, outflow = 0.0;
  for (int i = 0; i < 600'000; ++i) {
    if (i % 2000 == 0) {
      inflow = next();
      outflow = next() < 0.3 ? 0.0 : next();
    }
    cavity.step(inflow, outflow, 1e-3);
  }
  const FluidTotals& t = cavity.totals();
  EXPECT_GT(t.used, 100e-6);  // more than 100 ml went through
  EXPECT_NEAR(balance_error(cavity), 0.0, 1e-12 * t.used);
  EXPECT_NEAR(t.deficit(), cavity.channels().cavity_compliance * cavity.pressure() + t.absorbed,
              1e-12 * t.used);
}

TEST(DistensionBalance, an_opened_vessel_bleeds_below_its_pressure_and_takes_fluid_above_it) {
  // A cut artery (85 mmHg) and a capillary bed (25 mmHg) while the pump fills the cavity at
  // 100 mmHg: bleeding first, intravasation once the cavity passes each vessel's pressure. The
  // split at each crossing makes the result independent of the step.
  const std::vector<VesselOpening> openings{{2.0e-11, 11300.0}, {4.0e-12, 3300.0}};
  DistensionBalance fine(saline()), coarse(saline());
  fine.set_openings(openings);
  coarse.set_openings(openings);
  for (int i = 0; i < 30000; ++i)
    fine.step(1.0, 0.05, 1e-3);  // 30 s
  for (int i = 0; i < 6; ++i)
    coarse.step(1.0, 0.05, 5.0);
  const FluidTotals& t = fine.totals();
  ASSERT_GT(fine.pressure(), 11300.0);
  EXPECT_GT(t.bled, 0.0);
  EXPECT_GT(t.intravasated, 0.0);
  EXPECT_NEAR(balance_error(fine), 0.0, 1e-12 * t.used);
  EXPECT_NEAR(balance_error(coarse), 0.0, 1e-12 * t.used);
  EXPECT_NEAR(coarse.pressure(), fine.pressure(), 1e-7 * fine.pressure());
  EXPECT_NEAR(coarse.totals().bled, t.bled, 1e-7 * t.bled);
  EXPECT_NEAR(coarse.totals().intravasated, t.intravasated, 1e-7 * t.intravasated);
  // The last step's volumes are what each path passed: both take fluid now.
  ASSERT_EQ(coarse.last_step_volumes().size(), 2u);
  EXPECT_LT(coarse.last_step_volumes()[0], 0.0);
  EXPECT_LT(coarse.last_step_volumes()[1], 0.0);
  EXPECT_NEAR(t.uptake(), t.absorbed + t.intravasated, 0.0);

  EXPECT_THROW(fine.set_openings({{-1.0, 100.0}}), core::UsageError);
}

TEST(DistensionBalance, closed_valves_hold_the_pressure_and_absorption_stops_at_its_threshold) {
  DistensionBalance cavity(saline());
  for (int i = 0; i < 10; ++i)
    cavity.step(1.0, 1.0, 1.0);
  const double held = cavity.pressure();
  const FluidTotals before = cavity.totals();
  cavity.step(0.0, 0.0, 30.0);
  EXPECT_EQ(cavity.pressure(), held);
  EXPECT_EQ(cavity.totals().used, before.used);

  for (int i = 0; i < 120; ++i)
    cavity.step(1.0, 0.0, 1.0);  // above the threshold now
  const double threshold = cavity.channels().absorption_threshold;
  ASSERT_GT(cavity.pressure(), threshold);
  for (int i = 0; i < 100; ++i) {
    cavity.step(0.0, 0.0, 5.0);
    ASSERT_GE(cavity.pressure(), threshold);  // absorption only drains down to the threshold
  }
  EXPECT_NEAR(cavity.pressure(), threshold, 1e-6 * threshold);
}

TEST(DistensionBalance, overload_is_reached_when_the_deficit_reaches_the_limit) {
  core::FluidSpec fluid = saline();
  fluid.overload_volume = 10e-6;  // 10 ml
  DistensionBalance cavity(fluid);
  double overloaded_at = -1.0;
  for (int i = 0; i < 600'000 && overloaded_at < 0.0; ++i) {
    cavity.step(1.0, 0.0, 1e-3);
    if (cavity.overloaded()) overloaded_at = (i + 1) * 1e-3;
  }
  ASSERT_GT(overloaded_at, 0.0);
  EXPECT_GE(cavity.totals().deficit(), 10e-6);
  EXPECT_LT(cavity.totals().deficit(), 10e-6 + 1e-8);  // found within one step
}

TEST(DistensionBalance, negative_pressures_are_refused_naming_the_member) {
  core::FluidSpec fluid = saline();
  fluid.outflow_pressure = -100.0;
  try {
    DistensionBalance cavity(fluid);
    FAIL() << "a negative drain pressure was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/scenario/fluid/outflow_pressure"), std::string::npos);
  }
  fluid = saline();
  fluid.overload_volume = 0.0;
  EXPECT_THROW(DistensionBalance{fluid}, core::InputError);
}

}  // namespace
}  // namespace viscera::sim
