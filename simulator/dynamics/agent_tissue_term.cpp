#include "simulator/dynamics/agent_tissue_term.h"

#include "core/error.h"
#include "simulator/collision/penetration_depth.h"
#include "simulator/dynamics/spring_hessian.h"

namespace viscera::sim {

AgentTissueTerm::AgentTissueTerm(std::shared_ptr<const BodyModel> model,
                                 const SimulationState& state, core::CellTissueSpec spec,
                                 double time_step, const std::string& where)
    : BodyTerm(std::move(model)), spec_(std::move(spec)), time_step_(time_step) {
  if (!(time_step_ > 0.0))
    throw core::UsageError("the cell tissue of \"" + spec_.object + "\" needs a positive step");
  if (spec_.cell_types.size() != this->model().mesh.nodes.size()) {
    throw core::InputError("the cell tissue of \"" + spec_.object + "\" gives " +
                               std::to_string(spec_.cell_types.size()) + " cell types for " +
                               std::to_string(this->model().mesh.nodes.size()) + " cells",
                           {"", where + "/cell_types", spec_.object});
  }
  for (std::size_t i = 0; i < spec_.cell_types.size(); ++i) {
    const int t = spec_.cell_types[i];
    if (t < 0 || t >= static_cast<int>(spec_.types.size())) {
      throw core::InputError("the cell tissue of \"" + spec_.object + "\": cell type index " +
                                 std::to_string(t) + " of cell " + std::to_string(i) +
                                 " is not one of its " + std::to_string(spec_.types.size()) +
                                 " types",
                             {"", where + "/cell_types/" + std::to_string(i), spec_.object});
    }
  }
  types_ = cell_types_of(spec_);
  initialise(state);
}

void AgentTissueTerm::build(const SimulationState& state, int first) {
  first_ = first;
  const auto rest = state.range(state.rest_positions, model().body);
  homes_.assign(rest.begin(), rest.end());
  const auto& homes = homes_;
  connections_ = discover_cell_connections(homes, types_, spec_.cell_types, spec_.neighbour_radius,
                                           spec_.max_neighbours);
  const std::size_t n = homes.size();
  home_stiffness_.resize(n);
  damping_.resize(n);
  radius_.resize(n);
  efficiency_.resize(n);
  mass_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CellType& type = types_[static_cast<std::size_t>(spec_.cell_types[i])];
    mass_[i] = state.masses[static_cast<std::size_t>(first) + i];
    home_stiffness_[i] = type.home_stiffness;
    damping_[i] = mass_[i] * type.damping / time_step_;
    radius_[i] = type.radius;
    efficiency_[i] = type.collision_efficiency;
  }
}

double AgentTissueTerm::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  const auto& homes = homes_;
  for (const auto& c : connections_) {
    const double stretch =
        (x[static_cast<std::size_t>(first_ + c.b)] - x[static_cast<std::size_t>(first_ + c.a)])
            .norm() -
        c.rest_length;
    e += 0.5 * c.stiffness * stretch * stretch;
  }
  for (std::size_t i = 0; i < homes.size(); ++i)
    e += 0.5 * home_stiffness_[i] *
         (x[static_cast<std::size_t>(first_) + i] - homes[i]).squaredNorm();
  return e;
}

double AgentTissueTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                                   std::span<Vec3> f) const {
  double e = 0.0;
  const auto& homes = homes_;
  for (const auto& c : connections_) {
    const auto a = static_cast<std::size_t>(first_ + c.a);
    const auto b = static_cast<std::size_t>(first_ + c.b);
    const Vec3 d = x[b] - x[a];
    const double length = d.norm();
    if (length <= 0.0) {
      e += 0.5 * c.stiffness * c.rest_length * c.rest_length;
      continue;
    }
    const double stretch = length - c.rest_length;
    e += 0.5 * c.stiffness * stretch * stretch;
    const Vec3 on_b = (-c.stiffness * stretch / length) * d;  // eq. 3
    f[b] += on_b;
    f[a] -= on_b;
    // Eq. 8–9: connected cells closer than their radii and approaching rebound.
    const auto ca = static_cast<std::size_t>(c.a), cb = static_cast<std::size_t>(c.b);
    if (length >= radius_[ca] + radius_[cb]) continue;
    const Vec3 normal = d / length;
    const double approach = (v[a] - v[b]).dot(normal);
    if (approach <= 0.0) continue;
    const double mass = 0.5 * (mass_[ca] + mass_[cb]);
    const double efficiency = 0.5 * (efficiency_[ca] + efficiency_[cb]);
    const Vec3 rebound = (0.5 * efficiency * mass * approach * approach) * normal;
    f[a] -= rebound;
    f[b] += rebound;
  }
  for (std::size_t i = 0; i < homes.size(); ++i) {
    const std::size_t g = static_cast<std::size_t>(first_) + i;
    const Vec3 away = x[g] - homes[i];
    e += 0.5 * home_stiffness_[i] * away.squaredNorm();
    f[g] -= home_stiffness_[i] * away + damping_[i] * v[g];  // eq. 4 and eq. 6's damping
  }
  return e;
}

void AgentTissueTerm::declare_blocks(BlockPattern& pattern) const {
  for (const auto& c : connections_)
    pattern.add(first_ + c.a, first_ + c.b);
}

void AgentTissueTerm::add_stiffness(std::span<const Vec3> x, double scale, bool project,
                                    BlockSparseMatrix& matrix) const {
  for (const auto& c : connections_) {
    const int a = first_ + c.a, b = first_ + c.b;
    const Vec3 d = x[static_cast<std::size_t>(b)] - x[static_cast<std::size_t>(a)];
    const double length = d.norm();
    if (length <= 0.0) continue;
    const Mat3 h = radial_hessian(d / length, length, c.stiffness * (length - c.rest_length),
                                  c.stiffness, project);
    add_pair_block(matrix, a, b, h, scale);
  }
  for (std::size_t i = 0; i < home_stiffness_.size(); ++i) {
    const int g = first_ + static_cast<int>(i);
    matrix.block(matrix.diagonal_slot(g)) += (scale * home_stiffness_[i]) * Mat3::Identity();
  }
}

void AgentTissueTerm::add_damping(std::span<const Vec3> /*x*/, double scale,
                                  BlockSparseMatrix& matrix) const {
  for (std::size_t i = 0; i < damping_.size(); ++i) {
    const int g = first_ + static_cast<int>(i);
    matrix.block(matrix.diagonal_slot(g)) += (scale * damping_[i]) * Mat3::Identity();
  }
}

void AgentTissueTerm::after_step(const SimulationState& state) {
  const int body = model().body;
  const auto cells = state.range(state.positions, body);
  for (const auto& c : tear_and_yield(cells, connections_)) {
    const double length =
        (cells[static_cast<std::size_t>(c.b)] - cells[static_cast<std::size_t>(c.a)]).norm();
    tears_.push_back(
        {state.time, model().name, c.a, c.b, length / c.original_length - 1.0, c.tear_strain});
  }
}

int AgentTissueTerm::cut(const SimulationState& state, const Vec3& a, const Vec3& b,
                         const Vec3& c) {
  const auto cells = state.range(state.positions, model().body);
  const auto before = connections_.size();
  std::erase_if(connections_, [&](const CellConnection& link) {
    return segment_triangle_intersection(cells[static_cast<std::size_t>(link.a)],
                                         cells[static_cast<std::size_t>(link.b)], a, b, c) >= 0.0;
  });
  return static_cast<int>(before - connections_.size());
}

}  // namespace viscera::sim
