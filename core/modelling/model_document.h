#pragma once
/// A modelled object as the studio and the CLI edit it (seed 001 §3.3): one of KisMo's three
/// object types — a ball, a flat sheet or a (branching) pipe — shaped by its control points,
/// optionally layered into a volumetric body, with a material, fixed regions, an organ group
/// and connections to other objects at their nearest knots. It is stored as JSON
/// (format "viscera-model", version 1) and turned into a scene object by model_scene.h.
/// Positions and lengths in m.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/modelling/layered_body.h"
#include "core/modelling/pipe_network.h"
#include "core/primitives/ball_primitive.h"
#include "core/primitives/flat_primitive.h"
#include "core/scenario/material.h"
#include "core/scenario/scene_object.h"

namespace viscera::core {

inline constexpr const char* kModelFormat = "viscera-model";
inline constexpr int kModelFormatVersion = 1;

/// The object type of a model.
enum class ModelKind { Ball, Flat, Pipe };
std::string to_string(ModelKind kind);
/// Parses "ball", "flat" or "pipe"; throws UsageError otherwise.
ModelKind model_kind_from_string(const std::string& name);

/// How a model becomes a volumetric simulation body (layered_body.h).
struct ModelLayering {
  LayerOptions layers;       ///< copies, thickness (m), offset or scale
  bool mass_spring = false;  ///< KisMo's spring net instead of gmsh tets (the default)
  double cell_size = 0.0;    ///< m, gmsh tets; 0 = thickness / layers
  bool operator==(const ModelLayering&) const = default;
};

/// A ball of body nodes held still in the simulation.
struct FixedRegion {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;  ///< m
  bool operator==(const FixedRegion&) const = default;
};

/// A request to connect this model's body to another object's at the nearest knots within
/// `distance` (object_connectivity.h); resolved when the scene is built.
struct ModelConnection {
  std::string object;        ///< the other model's id
  double distance = 0.0;     ///< m
  double stiffness = 100.0;  ///< N/m per knot pair
  bool operator==(const ModelConnection&) const = default;
};

/// One modelled object.
struct ModelDocument {
  std::string id;  ///< [a-z0-9_-]+, the scene object's id
  std::string name;
  ObjectRole role = ObjectRole::Organ;
  std::string group;  ///< organ group, or empty
  ModelKind kind = ModelKind::Ball;
  BallPrimitive ball;  ///< when kind is Ball
  FlatPrimitive flat;  ///< when kind is Flat
  PipeNetwork pipe;    ///< when kind is Pipe
  /// Layered body; without it a closed surface is filled with gmsh tets and an open sheet has
  /// no body.
  std::optional<ModelLayering> layering;
  std::optional<Material> material;
  std::vector<FixedRegion> fixed;
  std::vector<ModelConnection> connections;
  bool operator==(const ModelDocument&) const = default;
};

/// Throws UsageError naming the model and the field when the document is inconsistent (id,
/// primitive, layering, fixed regions, connections).
void check_model(const ModelDocument& model);

/// The control points of the model's primitive in their edit order (ball: its control points;
/// flat: row-major; pipe: network_control_points).
std::vector<Vec3> model_control_points(const ModelDocument& model);

/// Moves control point `index` to `position`. Throws UsageError for an index out of range.
void move_model_control_point(ModelDocument& model, int index, const Vec3& position);

/// Adds a child branch to a pipe model and returns its index. Throws UsageError for a model
/// that is not a pipe or a branch that check_pipe_network refuses (the model is unchanged).
int add_model_branch(ModelDocument& model, const PipeBranch& branch);

/// The JSON document; dumping it gives the same bytes for the same model.
nlohmann::json model_to_json(const ModelDocument& model);

/// Parses a model document. Throws InputError naming `file` and the JSON pointer of a missing
/// or mistyped member, UnsupportedVersionError for a newer version, ValidationError when
/// check_model refuses it.
ModelDocument model_from_json(const nlohmann::json& json, const std::string& file);

}  // namespace viscera::core
