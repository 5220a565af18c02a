// Collision, contact and haptics figures of issue 7 against the seed papers: a spatial-hash
// query of 20k tets against 6k vertices (Teschner 2003: 70 ms), penetration depth per colliding
// point (Heidelberger 2004: 35 µs), proxy updates on a 10k-triangle surface, and the UDP device
// round trip on loopback.

#include <benchmark/benchmark.h>

#include <algorithm>

#include "core/random.h"
#include "simulator/collision/penetration_depth.h"
#include "simulator/collision/spatial_hash.h"
#include "simulator/haptics/haptic_proxy.h"
#include "simulator/haptics/simulated_device.h"
#include "simulator/haptics/udp_device_bridge.h"
#include "tests/support/tet_block.h"

namespace {

using viscera::core::Vec3;
using namespace viscera::sim;

void BM_SpatialHashQuery(benchmark::State& state) {
  // A: 15 × 15 × 15 cubes = 20,250 tets. B: 18³ = 5,832 vertices (a point body, no tets)
  // overlapping half of A, as in Teschner et al.'s 20k-tet / 6k-vertex scene.
  auto a = viscera::testing::tet_block(15, 15, 15, 0.004);
  auto b = viscera::testing::tet_block(17, 17, 17, 0.004);
  b.tets.clear();
  for (auto& n : b.nodes)
    n += Vec3(0.0301, 0.0011, 0.0013);
  viscera::core::Rng rng(3);
  for (auto& n : a.nodes)
    n += Vec3(rng.uniform(-4e-4, 4e-4), rng.uniform(-4e-4, 4e-4), rng.uniform(-4e-4, 4e-4));
  const std::vector<CollisionBodyView> bodies = {{a.nodes, a.tets}, {b.nodes, b.tets}};
  SpatialHash hash(mean_edge_length(bodies), 2 * (a.nodes.size() + b.nodes.size()) + 1);
  std::size_t contacts = 0;
  for (auto _ : state) {
    contacts = hash.detect(bodies, false).size();
    benchmark::DoNotOptimize(contacts);
  }
  state.counters["tets"] = static_cast<double>(a.tets.size() + b.tets.size());
  state.counters["vertices"] = static_cast<double>(a.nodes.size() + b.nodes.size());
  state.counters["contacts"] = static_cast<double>(contacts);
}
BENCHMARK(BM_SpatialHashQuery)->Unit(benchmark::kMillisecond);

void BM_PenetrationDepthPerPoint(benchmark::State& state) {
  // A block pressed 3 cm deep into a slab: about a thousand colliding points in 4 layers.
  auto slab = viscera::testing::tet_block(20, 20, 10, 0.005);
  for (auto& n : slab.nodes)
    n += Vec3(-0.05, -0.05, -0.05);
  auto block = viscera::testing::tet_block(14, 14, 10, 0.005);
  for (auto& n : block.nodes)
    n += Vec3(-0.0351, -0.0349, -0.0173);
  const std::vector<CollisionBodyView> bodies = {{block.nodes, block.tets},
                                                 {slab.nodes, slab.tets}};
  SpatialHash hash(mean_edge_length(bodies), 20011);
  std::vector<int> colliding;
  for (const auto& c : hash.detect(bodies, false)) {
    if (c.vertex_body == 0 && (colliding.empty() || colliding.back() != c.vertex))
      colliding.push_back(c.vertex);
  }
  std::vector<std::array<int, 2>> edges;
  for (const auto& t : block.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        edges.push_back({std::min(t[a], t[b]), std::max(t[a], t[b])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const auto adjacency = VertexAdjacency::from_edges(block.nodes.size(), edges);
  const PenetratedSurface surface{slab.nodes, slab.surface_faces};
  for (auto _ : state) {
    benchmark::DoNotOptimize(penetration_depths(block.nodes, adjacency, colliding, surface));
  }
  state.counters["colliding_points"] = static_cast<double>(colliding.size());
  state.counters["per_point"] = benchmark::Counter(
      static_cast<double>(colliding.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PenetrationDepthPerPoint)->Unit(benchmark::kMicrosecond);

void BM_HapticProxyUpdate(benchmark::State& state) {
  // A 70 × 70 sheet: 9,800 triangles. In contact the proxy walks; free it tests every face.
  const int n = 70;
  std::vector<Vec3> x;
  std::vector<viscera::core::Triangle> faces;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      x.emplace_back(-0.05 + 0.1 * i / n, -0.05 + 0.1 * j / n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      faces.push_back({a, a + 1, a + n + 2});
      faces.push_back({a, a + n + 2, a + n + 1});
    }
  const ProxySurface surface(faces);
  HapticProxy proxy(200.0);
  const bool in_contact = state.range(0) == 1;
  proxy.reset({0.0, 0.0, 0.01});
  double phase = 0.0;
  for (auto _ : state) {
    phase += 1e-3;
    const Vec3 tip(0.03 * std::sin(phase), 0.03 * std::cos(phase), in_contact ? -0.002 : 0.005);
    proxy.update(tip, surface, x);
    benchmark::DoNotOptimize(proxy.force());
  }
  state.counters["triangles"] = static_cast<double>(faces.size());
  state.counters["updates_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_HapticProxyUpdate)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_DeviceBridgeRoundTrip(benchmark::State& state) {
  UdpDeviceBridge bridge;
  SimulatedDevice device(bridge.port());
  DevicePose pose;
  DeviceFeedback feedback;
  for (auto _ : state) {
    ++pose.sequence;
    device.send(pose);
    while (!bridge.poll(100)) {
    }
    feedback.sequence = pose.sequence;
    bridge.send_feedback(feedback);
    benchmark::DoNotOptimize(device.receive(100));
  }
  state.counters["round_trips_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DeviceBridgeRoundTrip)->Unit(benchmark::kMicrosecond);

}  // namespace
