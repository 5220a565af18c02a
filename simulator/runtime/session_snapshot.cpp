#include "simulator/runtime/session_snapshot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "simulator/session/retired_tissue.h"
#include "simulator/session/session_runner.h"

namespace viscera::sim {

void capture_snapshot(const SessionRunner& runner, SessionSnapshot& out) {
  const World& world = runner.world();
  out.steps = world.steps();
  out.time = world.time();
  out.bodies.resize(world.bodies().size());
  for (std::size_t b = 0; b < world.bodies().size(); ++b) {
    const BodyView& body = world.bodies()[b];
    if (out.bodies[b].name != body.name()) out.bodies[b].name = body.name();
    out.bodies[b].positions.assign(body.positions().begin(), body.positions().end());
    out.bodies[b].coagulated.clear();
    out.bodies[b].cut_surface = runner.visible_surfaces() != nullptr
                                    ? runner.visible_surfaces()->cut_surface(static_cast<int>(b))
                                    : nullptr;
    if (const LaparoscopicTools* tools = runner.tools();
        tools != nullptr && b < tools->coagulated().size()) {
      const std::vector<std::uint8_t>& flags = tools->coagulated()[b];
      if (std::find(flags.begin(), flags.end(), 1) != flags.end())
        out.bodies[b].coagulated.assign(flags.begin(), flags.end());
    }
  }
  out.instrument = runner.instrument_state();
  out.optics_angle = runner.instrument().optics_angle;
  out.instrument_force = runner.instrument_force();
  out.time_limit = runner.time_limit();
  const SessionReport& report = runner.report();
  out.force_warning = report.force_warning;
  out.surface_seen = runner.coverage() != nullptr ? runner.coverage()->fraction_seen() : 0.0;
  out.step.clear();
  const int step = runner.current_step();
  if (step >= 0 && static_cast<std::size_t>(step) < report.procedure_steps.size()) {
    const StepResult& result = report.procedure_steps[static_cast<std::size_t>(step)];
    out.step = result.name.empty() ? result.id : result.name;
  }
  out.ended = runner.finished() ? report.end_reason : std::string();
  out.blood.clear();
  out.blood_stage.clear();
  out.haze_density = 0.0;
  out.bubbles.clear();
  out.bubble_size.clear();
  out.debris.clear();
  out.debris_size.clear();
  out.irrigation_drops.clear();
  out.irrigation_drop_age.clear();
  if (const SuctionIrrigation* cannula = runner.irrigation()) {
    const fluid::IrrigationJet& jet = cannula->jet();
    for (const fluid::JetDrop& drop : jet.drops()) {
      out.irrigation_drops.push_back(drop.position);
      out.irrigation_drop_age.push_back(
          static_cast<float>(std::min(1.0, drop.age / jet.options().max_flight)));
    }
  }
  out.smoke.clear();
  out.lens_fog = 0.0;
  out.tools = runner.tools() != nullptr;
  if (const LaparoscopicTools* tools = runner.tools()) {
    out.smoke = tools->smoke().billboards();
    out.lens_fog = tools->smoke().lens_fog();
  }
  out.pool_volume = 0.0;
  out.pool_blood_fraction = 0.0;
  out.pool_radius = 0.0;
  out.pool_waves.clear();
  if (const SuctionIrrigation* cannula = runner.irrigation()) {
    const fluid::FluidPool& pool = cannula->pool();
    out.pool_volume = pool.contents().total();
    out.pool_blood_fraction = pool.blood_fraction();
    if (out.pool_volume > 0.0) {
      out.pool_up = -pool.down();
      out.pool_centre = pool.floor() + pool.height() * out.pool_up;
      out.pool_radius = std::sqrt(pool.area() / std::numbers::pi);
      for (const fluid::PoolBubble& b : cannula->bubbles().bubbles()) {
        const fluid::PoolBubbleOptions& o = cannula->bubbles().options();
        out.bubbles.push_back(b.position);
        out.bubble_size.push_back(static_cast<float>(
            o.max_radius > o.min_radius ? (b.radius - o.min_radius) / (o.max_radius - o.min_radius)
                                        : 1.0));
      }
      const fluid::PoolWaves& waves = cannula->waves();
      out.pool_waves.push_back(static_cast<float>(waves.elevation_at(0.0, 0.0)));
      for (int k = 1; k <= SessionSnapshot::kPoolRings; ++k)
        for (int side = 0; side < SessionSnapshot::kPoolSides; ++side) {
          const double r = out.pool_radius * k / SessionSnapshot::kPoolRings;
          const double angle = 2.0 * std::numbers::pi * side / SessionSnapshot::kPoolSides;
          out.pool_waves.push_back(
              static_cast<float>(waves.elevation_at(r * std::cos(angle), r * std::sin(angle))));
        }
    }
  }
  if (const fluid::CavityFlow* flow = runner.cavity_flow()) {
    const fluid::BloodParticles& particles = flow->particles();
    out.blood.assign(particles.positions().begin(), particles.positions().end());
    out.blood_stage.resize(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i)
      out.blood_stage[i] = static_cast<float>(particles.stage(i));
    const fluid::AirBubbles& bubbles = flow->bubbles();
    out.bubbles.assign(bubbles.positions().begin(), bubbles.positions().end());
    const fluid::AirBubbleSettings& range = flow->settings().bubbles;
    const double span = range.max_radius - range.min_radius;
    out.bubble_size.resize(bubbles.size());
    for (std::size_t i = 0; i < bubbles.size(); ++i)
      out.bubble_size[i] =
          static_cast<float>(span > 0.0 ? (bubbles.radii()[i] - range.min_radius) / span : 0.0);
    const fluid::SuspendedParticles& debris = flow->debris();
    out.debris.assign(debris.positions().begin(), debris.positions().end());
    const double largest = equivalent_radius(kDebrisVolume);
    out.debris_size.resize(debris.size());
    for (std::size_t i = 0; i < debris.size(); ++i)
      out.debris_size[i] = static_cast<float>(std::min(1.0, debris.radii()[i] / largest));
    const double depth = flow->settings().view_depth;
    const double transmission =
        flow->view_transmission(camera_pose(out.instrument).tip,
                                view_direction(camera_pose(out.instrument), out.optics_angle));
    if (depth > 0.0 && transmission > 0.0) out.haze_density = -std::log(transmission) / depth;
  }
}

}  // namespace viscera::sim
