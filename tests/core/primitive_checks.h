#pragma once
/// Geometric checks shared by the primitive and modelling tests.

#include <gtest/gtest.h>

#include "core/mesh/surface_mesh.h"

namespace viscera::testing {

/// Watertight (every edge shared by two triangles in opposite directions) and outward
/// (positive enclosed volume), with no degenerate triangle.
::testing::AssertionResult is_watertight_and_outward(const core::SurfaceMesh& mesh);

/// Largest angle in radians between the normals of two triangles sharing an edge.
double max_dihedral_turn(const core::SurfaceMesh& mesh);

}  // namespace viscera::testing
