#include "simulator/dynamics/hydrometra_sweep.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/error.h"
#include "core/log.h"
#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/cavity_pressure.h"
#include "simulator/dynamics/teschner_terms.h"

namespace viscera::sim {
namespace {

/// The cavity pressure as a dead load during one backward Euler step (E = −f·x, no Hessian),
/// refreshed from the current shape before each step: a follower load solved by fixed point.
class CavityPressureLoad : public ForceTerm {
 public:
  explicit CavityPressureLoad(const CavitySurface& cavity) : cavity_(cavity) {}
  std::string name() const override { return "cavity-pressure"; }
  void set_pressure(double pressure) { pressure_ = pressure; }
  /// Loads at positions `x`, N.
  void update(std::span<const Vec3> x) {
    loads_.assign(x.size(), Vec3::Zero());
    add_pressure_load(cavity_, pressure_, x, loads_);
  }
  const std::vector<Vec3>& loads() const { return loads_; }
  void prepare(const SimulationState& state, const StepContext&) override {
    update(state.positions);
  }
  double energy(std::span<const Vec3> x) const override {
    double e = 0.0;
    for (std::size_t i = 0; i < loads_.size(); ++i)
      e -= loads_[i].dot(x[i]);
    return e;
  }
  double add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                    std::span<Vec3> f) const override {
    for (std::size_t i = 0; i < loads_.size(); ++i)
      f[i] += loads_[i];
    return energy(x);
  }
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}

 private:
  const CavitySurface& cavity_;
  double pressure_ = 0.0;
  std::vector<Vec3> loads_;
};

std::shared_ptr<BodyModel> body_model_of(const core::SceneObject& object,
                                         const std::map<std::string, core::Material>& materials) {
  core::Material base;
  if (!object.material.empty()) {
    const auto it = materials.find(object.material);
    if (it == materials.end())
      throw core::InputError("unknown material id \"" + object.material + "\"",
                             {"", "", "object " + object.id});
    base = it->second;
  }
  auto model = std::make_shared<BodyModel>();
  model->name = object.id;
  model->kind = BodyModelKind::Teschner;
  model->mesh = object.body;
  model->surface = object.body.surface_faces.empty() ? core::boundary_faces(object.body.tets)
                                                     : object.body.surface_faces;
  assign_layer_materials(*model, object, base, materials);
  return model;
}

}  // namespace

core::HydrometraStates sweep_hydrometra(const core::SceneObject& object,
                                        const std::map<std::string, core::Material>& materials,
                                        const HydrometraSweepSettings& settings,
                                        core::Progress& progress) {
  if (settings.states < 2 || !(settings.max_pressure > 0.0) ||
      !(settings.relative_residual > 0.0) || settings.max_iterations < 1 ||
      !(settings.pseudo_step > 0.0))
    throw core::UsageError("hydrometra sweep settings are out of range");
  if (object.body.tets.empty())
    throw core::UsageError("object " + object.id + " has no tets for a hydrometra sweep");
  const CavitySurface cavity = cavity_surface(object);
  if (cavity.empty())
    throw core::UsageError("object " + object.id + " marks no cavity for a hydrometra sweep");

  const std::shared_ptr<BodyModel> model = body_model_of(object, materials);
  const core::TetMesh& mesh = object.body;
  const std::vector<double> mass = mesh.node_mass.empty()
                                       ? core::lumped_node_masses(mesh, model->materials[0].density)
                                       : mesh.node_mass;
  SimulationState state;
  model->body = state.add_body(object.id, mesh.nodes, mass, mesh.fixed);
  std::vector<std::unique_ptr<ForceTerm>> owned;
  owned.push_back(std::make_unique<TeschnerDistanceTerm>(model, state));
  owned.push_back(std::make_unique<TeschnerAreaTerm>(model, state));
  owned.push_back(std::make_unique<TeschnerVolumeTerm>(model, state));
  auto load_term = std::make_unique<CavityPressureLoad>(cavity);
  CavityPressureLoad& load = *load_term;
  owned.push_back(std::move(load_term));
  std::vector<ForceTerm*> terms;
  for (const auto& t : owned)
    terms.push_back(t.get());

  NewtonSettings newton;
  newton.max_newton_iterations = settings.newton_iterations;
  newton.relative_tolerance = 1e-3;
  newton.residual_tolerance = 0.0;
  newton.max_cg_iterations = settings.cg_iterations;
  newton.cg_tolerance = settings.cg_tolerance;
  BackwardEuler solver(newton);
  solver.topology_changed(state, terms);

  const std::size_t n = mesh.nodes.size();
  const std::vector<Vec3> zero(n, Vec3::Zero());
  std::vector<Vec3> forces(n);

  // Largest free-node force left at the current shape under the current pressure, and the
  // largest nodal pressure load there.
  const auto residual = [&](double& largest_load) {
    load.update(state.positions);
    std::fill(forces.begin(), forces.end(), Vec3::Zero());
    for (ForceTerm* t : terms)
      t->add_forces(state.positions, zero, forces);
    double worst = 0.0;
    largest_load = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (state.inverse_masses[i] == 0.0) continue;
      worst = std::max(worst, forces[i].norm());
      largest_load = std::max(largest_load, load.loads()[i].norm());
    }
    return worst;
  };

  // True when an edge of a tet is stretched beyond its material's plastic yield: the session
  // would give the wall a permanent set there (PlasticFlow) and tear it at the tearing strain.
  const auto beyond_yield = [&] {
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const auto& tet = mesh.tets[t];
      const double yield = model->material_of(static_cast<int>(t)).plastic_yield;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
          const auto i = static_cast<std::size_t>(tet[static_cast<std::size_t>(a)]);
          const auto j = static_cast<std::size_t>(tet[static_cast<std::size_t>(b)]);
          const double rest = (mesh.nodes[j] - mesh.nodes[i]).norm();
          if ((state.positions[j] - state.positions[i]).norm() > (1.0 + yield) * rest) return true;
        }
    }
    return false;
  };

  long long step = 0;
  // One sweep over `states` pressures up to `top` Pa from the rest shape. Returns the index of
  // the first state that did not converge, at which the wall had lost most of its stiffness
  // against the pressure (its limit point: past it the Teschner wall, which does not stiffen
  // with strain, balloons) or that stretches an edge beyond its plastic yield, or `states` when
  // all are elastic equilibria.
  const auto sweep = [&](double top, core::HydrometraStates& out) {
    out = {};
    out.node_count = static_cast<int>(n);
    out.pressures.assign(static_cast<std::size_t>(settings.states), 0.0);
    out.displacements.assign(static_cast<std::size_t>(settings.states) * n, Vec3::Zero());
    state.positions = state.rest_positions;
    progress.begin_stage("hydrometra pressure states", settings.states);
    progress.step();  // state 0: 0 Pa, the rest shape (zero displacement)
    std::vector<Vec3> previous(state.positions), before_previous(state.positions);
    double first_compliance = 0.0;
    for (int k = 1; k < settings.states; ++k) {
      progress.check_cancelled();
      const double pressure = top * k / (settings.states - 1);
      out.pressures[static_cast<std::size_t>(k)] = pressure;
      load.set_pressure(pressure);
      double largest_load = 0.0;
      // Warm start: the previous state, moved on along the last step's secant (states are
      // evenly spaced); kept only when it leaves less force than the previous state does.
      double left = residual(largest_load);
      if (k >= 2) {
        for (std::size_t i = 0; i < n; ++i)
          state.positions[i] = 2.0 * previous[i] - before_previous[i];
        double guess_load = 0.0;
        const double guessed = residual(guess_load);
        if (std::isfinite(guessed) && guessed < left) {
          left = guessed;
          largest_load = guess_load;
        } else {
          state.positions = previous;
          left = residual(largest_load);
        }
      }
      for (int it = 0;
           it < settings.max_iterations && left > settings.relative_residual * largest_load; ++it) {
        std::fill(state.velocities.begin(), state.velocities.end(), Vec3::Zero());
        solver.step(state, terms, {0.0, settings.pseudo_step, ++step});
        left = residual(largest_load);
        if (!std::isfinite(left)) break;
      }
      if (!(left <= settings.relative_residual * largest_load)) return k;
      // Compliance of this step, m/Pa: the largest nodal movement per pascal.
      double moved = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        moved = std::max(moved, (state.positions[i] - previous[i]).norm());
      const double compliance = moved / (pressure - out.pressures[static_cast<std::size_t>(k) - 1]);
      if (k == 1) first_compliance = compliance;
      if (compliance > settings.max_softening * first_compliance) return k;
      if (beyond_yield()) return k;
      out.residual = std::max(out.residual, left);
      before_previous = previous;
      previous = state.positions;
      for (std::size_t i = 0; i < n; ++i)
        out.displacements[static_cast<std::size_t>(k) * n + i] =
            state.positions[i] - state.rest_positions[i];
      progress.step();
    }
    return settings.states;
  };

  // The states 0 … count − 1 of a sweep that stopped at state `count` (each an equilibrium).
  const auto converged_prefix = [n](core::HydrometraStates partial, int count) {
    partial.pressures.resize(static_cast<std::size_t>(count));
    partial.displacements.resize(static_cast<std::size_t>(count) * n);
    return partial;
  };
  core::HydrometraStates states;
  int reached = sweep(settings.max_pressure, states);
  if (reached == settings.states) return states;
  // The wall gives way between state reached − 1 and reached: the states span the range it
  // holds, so they sweep again, evenly up to the last equilibrium found (again, should the
  // finer states meet the limit earlier). A wall that holds no pressure at all, or whose limit
  // keeps moving, keeps the equilibria it did reach — at the least its rest shape — so a
  // patient is never refused for its hydrometra.
  core::HydrometraStates best = converged_prefix(states, std::max(reached, 1));
  for (int pass = 0; reached < settings.states; ++pass) {
    if (reached < 2 || pass == 3) {
      core::logger()->warn(
          "hydrometra of {}: the wall holds no equilibrium beyond {:.1f} Pa in this model (too "
          "soft for distension), so it keeps {} state(s) up to there",
          object.id, best.pressures.back(), best.pressures.size());
      return best;
    }
    const double limit =
        settings.limit_fraction * states.pressures[static_cast<std::size_t>(reached) - 1];
    core::logger()->warn(
        "hydrometra of {}: at {:.0f} Pa the wall balloons or yields (Teschner energies do not "
        "stiffen with strain), so its {} states span 0 to {:.0f} Pa, short of that limit",
        object.id, states.pressures[static_cast<std::size_t>(reached)], settings.states, limit);
    reached = sweep(limit, states);
    if (reached > 1 &&
        states.pressures[static_cast<std::size_t>(reached) - 1] > best.pressures.back())
      best = converged_prefix(states, reached);
  }
  return states;
}

int add_hydrometra_states(core::Scenario& scenario, core::Progress& progress) {
  if (!scenario.fluid.enabled) return 0;
  int added = 0;
  for (core::SceneObject& object : scenario.objects) {
    if (object.role != core::ObjectRole::Organ || object.body_kind != core::BodyKind::TetMesh ||
        object.body.tets.empty() || cavity_surface(object).empty())
      continue;
    object.hydrometra = sweep_hydrometra(object, scenario.materials, {}, progress);
    ++added;
  }
  return added;
}

}  // namespace viscera::sim
