#include "simulator/session/suction_irrigation.h"

#include <cmath>
#include <limits>
#include <utility>

namespace viscera::sim {

namespace {

/// The bodies with tets and a surface, in world order.
std::vector<int> surface_bodies(const World& world) {
  std::vector<int> bodies;
  for (const auto& model : world.models())
    if (model->kind != BodyModelKind::CellAgent && !model->mesh.tets.empty() &&
        !model->surface.empty())
      bodies.push_back(model->body);
  return bodies;
}

core::Vec3 down_of(const World& world) {
  return world.gravity().norm() > 0.0 ? core::Vec3(world.gravity().normalized())
                                      : core::Vec3(-core::Vec3::UnitZ());
}

/// Barycentric coordinates of `p` over the triangle a, b, c (on its plane).
core::Vec3 barycentric(const core::Vec3& p, const core::Vec3& a, const core::Vec3& b,
                       const core::Vec3& c) {
  const core::Vec3 e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double d20 = d.dot(e0), d21 = d.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  if (!(std::abs(det) > 0.0)) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  const double v = (d11 * d20 - d01 * d21) / det;
  const double w = (d00 * d21 - d01 * d20) / det;
  return {1.0 - v - w, v, w};
}

}  // namespace

fluid::FluidPool pool_under(const World& world, const std::vector<int>& bodies, double area) {
  const core::Vec3 down = down_of(world);
  core::Vec3 floor = core::Vec3::Zero();
  double lowest = -std::numeric_limits<double>::infinity();
  for (const int b : bodies) {
    const auto rest = world.state().range(world.state().rest_positions, b);
    for (const core::Triangle& t : world.models()[static_cast<std::size_t>(b)]->surface) {
      for (const int n : t) {
        const core::Vec3& p = rest[static_cast<std::size_t>(n)];
        if (p.dot(down) > lowest) lowest = p.dot(down), floor = p;
      }
    }
  }
  return fluid::FluidPool(floor, down, area);
}

SuctionIrrigation::SuctionIrrigation(const World& world, SuctionIrrigationOptions options)
    : options_(options),
      bodies_(surface_bodies(world)),
      jet_(options.jet),
      pool_(pool_under(world, bodies_, options.pool_area)),
      waves_(pool_.floor(), pool_.down(), pool_.area()),
      surfaces_(bodies_.size()),
      triangles_(bodies_.size()) {}

void SuctionIrrigation::follow(const InstrumentState& state, World& world, double dt,
                               double blood_released, LaparoscopySummary& summary) {
  if (blood_released > blood_seen_) {
    pool_.add_blood(blood_released - blood_seen_);
    blood_seen_ = blood_released;
  }
  const bool cannula = state.tool == LaparoscopicTool::Suction;
  if (cannula && state.irrigating) jet_.emit(state.tip, state.axis, dt);
  impacts_.clear();
  landings_.clear();
  if (!jet_.drops().empty()) {
    refresh_surfaces(world);
    const fluid::SurfaceQuery query = [this](const core::Vec3& from, const core::Vec3& to) {
      return first_hit(from, to);
    };
    impacts_ = jet_.step(dt, world.gravity(), query, pool_);
    landings_ = jet_.last_landings();
    for (const fluid::PoolLanding& landing : landings_) {
      waves_.drop_lands(landing.point, landing.velocity, landing.volume, pool_.height());
      bubbles_.drop_lands(landing.point, landing.velocity, pool_);
    }
  }
  apply_impacts(world);
  const bool sucking = cannula && state.jaws_closed;
  if (sucking) pool_.suck(state.tip, options_.suction, dt);
  waves_.step(dt, pool_.height());
  bubbles_.step(dt, pool_, waves_, sucking, state.tip, options_.suction.reach);
  summary.irrigated_volume = jet_.emitted_volume();
  summary.suctioned_volume = pool_.suctioned().total();
  summary.pool_volume = pool_.contents().total();
  summary.pool_blood_fraction = pool_.blood_fraction();
}

void SuctionIrrigation::refresh_surfaces(const World& world) {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const int b = bodies_[i];
    const auto positions = world.state().range(world.state().positions, b);
    const std::vector<core::Triangle>& surface =
        world.models()[static_cast<std::size_t>(b)]->surface;
    if (triangles_[i] != surface || surfaces_[i].positions().size() != positions.size()) {
      triangles_[i] = surface;
      surfaces_[i] = SurfaceBvh(surface, positions);
    } else {
      surfaces_[i].refit(positions);
    }
  }
}

std::optional<fluid::SurfaceHit> SuctionIrrigation::first_hit(const core::Vec3& from,
                                                              const core::Vec3& to) const {
  const double length = (to - from).norm();
  if (!(length > 0.0)) return std::nullopt;
  const core::Vec3 direction = (to - from) / length;
  std::optional<fluid::SurfaceHit> best;
  double nearest = length;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const RayHit hit = surfaces_[i].cast(from, direction, length);
    if (hit.triangle < 0 || (best && hit.distance >= nearest)) continue;
    nearest = hit.distance;
    const core::Triangle& t = surfaces_[i].triangles()[static_cast<std::size_t>(hit.triangle)];
    const auto& x = surfaces_[i].positions();
    const core::Vec3 &a = x[static_cast<std::size_t>(t[0])], &b = x[static_cast<std::size_t>(t[1])],
                     &c = x[static_cast<std::size_t>(t[2])];
    fluid::SurfaceHit h;
    h.fraction = hit.distance / length;
    h.point = from + hit.distance * direction;
    const core::Vec3 normal = (b - a).cross(c - a);
    h.normal = normal.norm() > 0.0 ? core::Vec3(normal.normalized()) : core::Vec3(-direction);
    h.body = bodies_[i];
    h.nodes = t;
    h.weights = barycentric(h.point, a, b, c);
    best = h;
  }
  return best;
}

void SuctionIrrigation::apply_impacts(World& world) {
  if (impacts_.empty()) {
    if (forces_ != nullptr && !forces_->forces().empty()) forces_->clear();
    return;
  }
  if (forces_ == nullptr) {
    // Added at the first impact, so a session that never irrigates steps exactly as before.
    auto term = std::make_unique<ImpactForces>();
    forces_ = term.get();
    world.add_term(std::move(term));
  }
  std::vector<std::pair<int, core::Vec3>> forces;
  forces.reserve(3 * impacts_.size());
  for (const fluid::JetImpact& impact : impacts_) {
    const int first = world.state().body(impact.body).first;
    for (int k = 0; k < 3; ++k)
      forces.emplace_back(first + impact.nodes[static_cast<std::size_t>(k)],
                          impact.weights[k] * impact.force);
  }
  forces_->set(std::move(forces), world.state());
  world.wake();
}

}  // namespace viscera::sim
