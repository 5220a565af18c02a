// The world's rebuild after a cut (issue 17: a session's cut ≤ 2 ms): World::topology_changed on
// the polyp of `viscera new --template hysteroscopy-polypectomy --seed 1` with the instrument
// attached, as the resection loop calls it — every term's caches, the body contact's hash, the
// proxy's surface and the implicit solver's block pattern. The polyp is given its own topology
// again, which costs what a new one does (nothing is compared with the old).

#include <benchmark/benchmark.h>

#include "simulator/world/world.h"
#include "templates/template_catalog.h"

namespace {

using viscera::sim::BodyTopology;
using viscera::sim::unchanged_topology;
using viscera::sim::World;

void BM_WorldRebuildAfterCut(benchmark::State& state) {
  const auto scenario = viscera::templates::build_from_template("hysteroscopy-polypectomy", {}, 1);
  World world(scenario);
  const int polyp = world.body_index("polyp-1");
  world.attach_instrument(world.body_index("uterus"), 200.0, {0.0, 0.0, -1.0});
  const auto& model = *world.models()[static_cast<std::size_t>(polyp)];
  const BodyTopology topology =
      unchanged_topology(model.mesh, world.state().range(world.state().positions, polyp));
  for (auto _ : state)
    world.topology_changed(polyp, topology);
  state.counters["nodes"] = static_cast<double>(world.state().node_count());
}
BENCHMARK(BM_WorldRebuildAfterCut)->Unit(benchmark::kMillisecond);

}  // namespace
