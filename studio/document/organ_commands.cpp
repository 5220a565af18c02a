#include "studio/document/organ_commands.h"

#include <algorithm>

#include "core/error.h"

namespace viscera::studio {
namespace {

QString q(const std::string& text) {
  return QString::fromStdString(text);
}

core::SceneObject& object_by_id(core::Scenario& scenario, const std::string& id) {
  for (auto& object : scenario.objects) {
    if (object.id == id) return object;
  }
  throw core::UsageError("the scenario has no object \"" + id + "\"");
}

}  // namespace

ApplyTextureCommand::ApplyTextureCommand(ScenarioDocument& document, TexturedObject textured)
    : document_(document), new_(std::move(textured)) {
  const core::SceneObject* old = document_.scenario().find_object(new_.object.id);
  if (old == nullptr)
    throw core::UsageError("the scenario has no object \"" + new_.object.id + "\"");
  old_object_ = *old;
  const auto spec = document_.scenario().textures.find(new_.spec.id);
  if (spec != document_.scenario().textures.end()) old_spec_ = spec->second;
  for (const auto& [path, bytes] : new_.files) {
    const auto file = document_.files().find(path);
    old_files_[path] =
        file == document_.files().end() ? std::nullopt : std::optional<std::string>(file->second);
  }
  setText(QObject::tr("Texture %1 with %2").arg(q(new_.object.name), q(new_.spec.preset)));
}

void ApplyTextureCommand::redo() {
  auto& scenario = document_.edit_scenario();
  scenario.textures[new_.spec.id] = new_.spec;
  object_by_id(scenario, new_.object.id) = new_.object;
  for (const auto& [path, bytes] : new_.files)
    document_.edit_files()[path] = bytes;
  document_.notify_changed(ChangeKind::Objects, q(new_.object.id));
}

void ApplyTextureCommand::undo() {
  auto& scenario = document_.edit_scenario();
  object_by_id(scenario, new_.object.id) = old_object_;
  if (old_spec_) {
    scenario.textures[new_.spec.id] = *old_spec_;
  } else {
    scenario.textures.erase(new_.spec.id);
  }
  for (const auto& [path, bytes] : old_files_) {
    if (bytes) {
      document_.edit_files()[path] = *bytes;
    } else {
      document_.edit_files().erase(path);
    }
  }
  document_.notify_changed(ChangeKind::Objects, q(new_.object.id));
}

AddVesselTreeCommand::AddVesselTreeCommand(ScenarioDocument& document, core::VesselTree tree)
    : document_(document), tree_(std::move(tree)) {
  const auto& scenario = document_.scenario();
  if (std::any_of(scenario.vessel_trees.begin(), scenario.vessel_trees.end(),
                  [&](const auto& t) { return t.id == tree_.id; }))
    throw core::UsageError("the scenario already has a vessel tree \"" + tree_.id + "\"");
  if (scenario.find_object(tree_.host_object) == nullptr)
    throw core::UsageError("the scenario has no object \"" + tree_.host_object + "\"");
  setText(QObject::tr("Grow vessels %1").arg(q(tree_.id)));
}

void AddVesselTreeCommand::redo() {
  document_.edit_scenario().vessel_trees.push_back(tree_);
  document_.notify_changed(ChangeKind::Objects, q(tree_.host_object));
}

void AddVesselTreeCommand::undo() {
  std::erase_if(document_.edit_scenario().vessel_trees,
                [&](const auto& t) { return t.id == tree_.id; });
  document_.notify_changed(ChangeKind::Objects, q(tree_.host_object));
}

AddPathologyCommand::AddPathologyCommand(ScenarioDocument& document, PathologyParts parts)
    : document_(document), parts_(std::move(parts)) {
  const auto& scenario = document_.scenario();
  if (scenario.find_object(parts_.object.id) != nullptr ||
      std::any_of(scenario.pathologies.begin(), scenario.pathologies.end(),
                  [&](const auto& p) { return p.id == parts_.record.id; }))
    throw core::UsageError("the scenario already has a \"" + parts_.object.id + "\"");
  if (parts_.material && scenario.materials.contains(parts_.material->id)) parts_.material.reset();
  if (parts_.host) {
    const core::SceneObject* host = scenario.find_object(parts_.host->object.id);
    if (host == nullptr)
      throw core::UsageError("the scenario has no object \"" + parts_.host->object.id + "\"");
    old_host_ = RemeshedHost{*host, {}};
    for (const auto& moved : parts_.host->connections) {
      const auto it = std::find_if(scenario.connections.begin(), scenario.connections.end(),
                                   [&](const auto& c) { return c.id == moved.id; });
      if (it == scenario.connections.end())
        throw core::UsageError("the scenario has no connection \"" + moved.id + "\"");
      old_host_->connections.push_back(*it);
    }
  }
  setText(QObject::tr("Place %1").arg(q(parts_.record.id)));
}

void AddPathologyCommand::swap_host(const core::SceneObject& object,
                                    const std::vector<core::Connection>& connections) {
  auto& scenario = document_.edit_scenario();
  for (auto& existing : scenario.objects) {
    if (existing.id == object.id) existing = object;
  }
  for (auto& existing : scenario.connections) {
    for (const auto& connection : connections) {
      if (existing.id == connection.id) existing = connection;
    }
  }
  document_.notify_changed(ChangeKind::Objects, q(object.id));
}

void AddPathologyCommand::redo() {
  auto& scenario = document_.edit_scenario();
  if (parts_.host) swap_host(parts_.host->object, parts_.host->connections);
  if (parts_.material) scenario.materials[parts_.material->id] = *parts_.material;
  scenario.objects.push_back(parts_.object);
  scenario.pathologies.push_back(parts_.record);
  scenario.connections.push_back(parts_.connection);
  if (parts_.material) document_.notify_changed(ChangeKind::Materials, q(parts_.material->id));
  document_.notify_changed(ChangeKind::Objects, q(parts_.object.id));
}

void AddPathologyCommand::undo() {
  auto& scenario = document_.edit_scenario();
  std::erase_if(scenario.connections, [&](const auto& c) { return c.id == parts_.connection.id; });
  std::erase_if(scenario.pathologies, [&](const auto& p) { return p.id == parts_.record.id; });
  std::erase_if(scenario.objects, [&](const auto& o) { return o.id == parts_.object.id; });
  if (parts_.material) scenario.materials.erase(parts_.material->id);
  document_.notify_changed(ChangeKind::Objects, q(parts_.object.id));
  if (parts_.material) document_.notify_changed(ChangeKind::Materials, q(parts_.material->id));
  if (old_host_) swap_host(old_host_->object, old_host_->connections);
}

ReplaceMaterialCommand::ReplaceMaterialCommand(ScenarioDocument& document, core::Material material)
    : document_(document), new_(std::move(material)) {
  const auto it = document_.scenario().materials.find(new_.id);
  if (it == document_.scenario().materials.end())
    throw core::UsageError("the scenario has no material \"" + new_.id + "\"");
  old_ = it->second;
  setText(QObject::tr("Fit material %1").arg(q(new_.name)));
}

void ReplaceMaterialCommand::set(const core::Material& material) {
  document_.edit_scenario().materials[material.id] = material;
  document_.notify_changed(ChangeKind::Materials, q(material.id));
}

void ReplaceMaterialCommand::redo() {
  set(new_);
}

void ReplaceMaterialCommand::undo() {
  set(old_);
}

SetActiveDeformationCommand::SetActiveDeformationCommand(ScenarioDocument& document,
                                                         core::ActiveDeformation deformation)
    : document_(document), new_(std::move(deformation)) {
  if (document_.scenario().find_object(new_.target_object) == nullptr)
    throw core::UsageError("the scenario has no object \"" + new_.target_object + "\"");
  for (const auto& existing : document_.scenario().active_deformations) {
    if (existing.id == new_.id) old_ = existing;
  }
  setText(QObject::tr("Set %1").arg(q(new_.id)));
}

void SetActiveDeformationCommand::set(const std::optional<core::ActiveDeformation>& deformation) {
  auto& list = document_.edit_scenario().active_deformations;
  const auto it = std::find_if(list.begin(), list.end(),
                               [&](const auto& entry) { return entry.id == new_.id; });
  if (!deformation) {
    if (it != list.end()) list.erase(it);
  } else if (it != list.end()) {
    *it = *deformation;
  } else {
    list.push_back(*deformation);
  }
  document_.notify_changed(ChangeKind::Objects, q(new_.target_object));
}

void SetActiveDeformationCommand::redo() {
  set(new_);
}

void SetActiveDeformationCommand::undo() {
  set(old_);
}

}  // namespace viscera::studio
