#pragma once
/// Scene parts as asset library entries and back (issue 9 §7; seed 001 §3.3: models and
/// materials archived for reuse), without widgets.
///
/// - An object goes in as a model entry whose payload is a zipped scenario package (.vscz)
///   holding that object with its surface, body, embedding, materials (its own and its
///   layers') and texture (spec and baked maps): nothing is lost on the way back. Thumbnail:
///   its surface (textures/surface_thumbnail.h).
/// - A material goes in as a "viscera-material" JSON entry (core/materials/material_file.h),
///   with a plot of its stress-strain curve as thumbnail when it has a fitted one.
/// - A model entry comes back as the objects of its package (.vscz) or of a "viscera-model"
///   document (core/modelling/model_scene.h, as `viscera library add` stores them), renamed
///   where their ids, material or texture ids are taken in the target scenario.

#include <string>
#include <vector>

#include "core/library/asset_library.h"
#include "core/scenario/scenario.h"
#include "studio/document/scenario_document.h"

namespace viscera::studio {

/// Objects (with what they need) to add to a scenario in one step.
struct ModelParts {
  std::vector<core::SceneObject> objects;
  std::vector<core::Material> materials;      ///< only ids new to the target
  std::vector<core::TextureSpec> textures;    ///< only ids new to the target
  std::vector<core::Connection> connections;  ///< between the added objects
  PackageFiles files;                         ///< baked maps of the added textures
};

/// The model entry of object `object_id` of `content`, named `name` (e.g. the object id).
/// Throws core::UsageError for an unknown object, core::Error subclasses from packing.
core::AssetEntry object_asset_entry(const DocumentContent& content, const std::string& object_id,
                                    const std::string& name);

/// The material entry of `material`, named `name`.
core::AssetEntry material_asset_entry(const core::Material& material, const std::string& name);

/// The parts of model entry `entry`, renamed to fit into `target`. Throws core::UsageError for
/// an entry of another type or an unsupported payload format, core::InputError for a payload
/// that does not read.
ModelParts model_parts_from_asset(const core::AssetEntry& entry, const core::Scenario& target);

/// The material of material entry `entry`. Throws core::UsageError for another type,
/// core::InputError for a payload that does not read.
core::Material material_from_asset(const core::AssetEntry& entry);

}  // namespace viscera::studio
