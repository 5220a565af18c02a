// Soak (issue 21 §4): one long headless hysteroscopy session — the expert's tour repeated,
// with its wall contacts — sampling the process's resident memory at every thousandth of the
// session. Memory must stay flat after warm-up: everything a session keeps grows only with what
// the report records (the instrument path), never with the steps taken.
//   build/bin/viscera_soak_bench                       one simulated hour
//   VISCERA_SOAK_SECONDS=600 build/bin/viscera_soak_bench
// Counters: rss_warm_MB (resident set at 10 % of the session), rss_end_MB, rss_peak_MB,
// growth_percent = (end − warm) / warm · 100, real_time_factor = simulated / wall s.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/progress.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "tests/bench/session_scripts.h"

namespace {

/// Resident set size of this process, MB (/proc/self/statm).
double resident_megabytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / 1048576.0;
}

double soak_seconds() {
  const char* text = std::getenv("VISCERA_SOAK_SECONDS");
  const double seconds = text ? std::atof(text) : 3600.0;
  return seconds > 0.0 ? seconds : 3600.0;
}

void BM_HysteroscopySessionSoak(benchmark::State& state) {
  const double duration = soak_seconds();
  const auto json =
      viscera::bench::repeated(viscera::bench::hysteroscopy_script("expert"), duration);
  const auto input = viscera::sim::ScriptedTrajectory::from_json(json, "script", 30.0);
  const auto options = viscera::bench::scripted_run(input, duration);
  std::vector<std::pair<double, double>> samples;  // (fraction of the session, MB)
  viscera::core::Progress progress([&](double fraction, const std::string&) {
    samples.emplace_back(fraction, resident_megabytes());
  });
  // The procedure's own limit (10 minutes) would end the session early: the soak lifts it.
  viscera::core::Scenario patient = viscera::bench::hysteroscopy_patient();
  patient.session.duration_limit = std::max(patient.session.duration_limit, duration + 1.0);
  for (auto _ : state) {
    const auto report = viscera::sim::run_headless(patient, options, progress);
    state.counters["real_time_factor"] =
        report.wall_time > 0.0 ? report.simulated_time / report.wall_time : 0.0;
    state.counters["simulated_s"] = report.simulated_time;
    // What the report keeps: each series is bounded (SeriesThinning), the events are not.
    state.counters["samples"] = static_cast<double>(report.samples.size());
    state.counters["path"] = static_cast<double>(report.path.size());
    state.counters["checkpoints"] = static_cast<double>(report.checkpoints.size());
    state.counters["events"] = static_cast<double>(report.events.size());
    state.counters["inputs"] = static_cast<double>(report.inputs.size());
    if (report.simulated_time < duration - 1e-6) {
      state.SkipWithError(("the session ended (" + report.end_reason + ") after " +
                           std::to_string(report.simulated_time) + " s, short of the soak")
                              .c_str());
      return;
    }
  }
  const auto warm = std::find_if(samples.begin(), samples.end(),
                                 [](const auto& sample) { return sample.first >= 0.1; });
  if (warm == samples.end()) {
    state.SkipWithError("the session reported no progress after its first tenth");
    return;
  }
  double peak = 0.0;
  for (const auto& sample : samples)
    peak = std::max(peak, sample.second);
  state.counters["rss_warm_MB"] = warm->second;
  state.counters["rss_end_MB"] = samples.back().second;
  state.counters["rss_peak_MB"] = peak;
  state.counters["growth_percent"] = (samples.back().second - warm->second) / warm->second * 100.0;
}
BENCHMARK(BM_HysteroscopySessionSoak)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
