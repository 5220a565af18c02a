#pragma once
/// Scenarios built by hand for the package tests: every field of every part is set, so a round
/// trip that drops or mangles anything shows up as an inequality.

#include "core/scenario/scenario.h"

namespace viscera::testing {

/// A unit cube as five positive tets, with boundary faces, masses and one fixed node.
core::TetMesh cube_body();

/// A scenario that fills every struct field with a non-default value: two objects (one with a
/// tet body and an embedded surface, one surface-only), materials with a stress-strain curve,
/// a texture, a vessel tree, pulse and motility, a pathology, a connection, fluid, session
/// tasks, variability rules and provenance.
core::Scenario full_scenario();

}  // namespace viscera::testing
