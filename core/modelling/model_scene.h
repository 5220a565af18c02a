#pragma once
/// From model documents (model_document.h) to a scenario the simulator loads (seed 001 §3.3:
/// objects are shaped, layered into volumetric bodies, "connected with each other at their
/// mass knots with a nearest-neighbour approach and form organ model groups, which can be
/// combined to create the final surgical simulation scene").

#include <vector>

#include "core/modelling/model_document.h"
#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::core {

/// The model's visual surface: the primitive's tessellation (ball_primitive.h,
/// flat_primitive.h, pipe_network.h). A layered flat is tessellated as its open sheet, which
/// the layers turn into a slab. Throws as the tessellators.
SurfaceMesh tessellate_model(const ModelDocument& model, Progress& progress = Progress::none());

/// The model as a scene object: its surface, and its body —
///   layered, gmsh tets:   the shell between the surface and its innermost copy (TetMesh);
///   layered, mass-spring: KisMo's net of the copies (MassSpring);
///   not layered:          a closed surface filled with gmsh tets (TetMesh), an open sheet none —
/// with masses lumped from the material's density (default Material when it has none), nodes
/// inside a fixed region held, and the surface embedded in the body. Throws as the meshers,
/// and ValidationError naming the model when a fixed region holds no node.
SceneObject build_model_object(const ModelDocument& model, Progress& progress = Progress::none());

/// The scenario of `models`: one object each, their materials, organ groups, and each model's
/// connections resolved at the nearest knots (object_connectivity.h). Throws UsageError for
/// duplicate ids, ValidationError when two models give one material id different constants, a
/// connection names a model not among them, or finds no knots within its distance.
Scenario build_model_scenario(const std::vector<ModelDocument>& models,
                              Progress& progress = Progress::none());

}  // namespace viscera::core
