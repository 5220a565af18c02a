#pragma once
/// Bodies built by hand for the physics tests.

#include <memory>
#include <span>

#include "core/mesh/tet_mesh.h"
#include "core/random.h"
#include "core/scenario/material.h"
#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/force_term.h"
#include "simulator/dynamics/simulation_state.h"
#include "simulator/dynamics/teschner_terms.h"
#include "tests/support/tet_block.h"

namespace viscera::testing {

/// A flat square sheet at z = 0 facing +z, 2·half_width m wide, split into n × n squares of two
/// triangles each: a surface for proxy and instrument tests.
struct Sheet {
  std::vector<core::Vec3> positions;
  std::vector<core::Triangle> faces;
};
Sheet make_sheet(int n, double half_width);

/// One tet body alone in a SimulationState with its Teschner terms (one material), for the
/// physics tests of single terms.
struct TeschnerBody {
  TeschnerBody(const core::TetMesh& mesh, const core::Material& material);
  sim::SimulationState state;
  std::shared_ptr<sim::BodyModel> model;
  std::unique_ptr<sim::TeschnerDistanceTerm> distance;
  std::unique_ptr<sim::TeschnerAreaTerm> area;
  std::unique_ptr<sim::TeschnerVolumeTerm> volume;
  const sim::DistanceTerms& distance_terms() const { return distance->terms(); }
  const sim::AreaTerms& area_terms() const { return area->terms(); }
  const sim::VolumeTerms& volume_terms() const { return volume->terms(); }
  const std::vector<core::Vec3>& rest_positions() const { return state.rest_positions; }
  std::vector<sim::ForceTerm*> terms() const { return {distance.get(), area.get(), volume.get()}; }
};

/// A body model of `mesh` with one material (body 0 of a state).
std::shared_ptr<sim::BodyModel> one_material_model(const core::TetMesh& mesh,
                                                   const core::Material& material);

/// Moves every node by a random offset of up to `amplitude` m (core::Rng with `seed`).
void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed);

}  // namespace viscera::testing
