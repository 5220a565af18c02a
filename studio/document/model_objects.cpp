#include "studio/document/model_objects.h"

#include <algorithm>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "core/modelling/model_scene.h"
#include "core/package/scenario_package.h"
#include "core/package/zip_archive.h"

namespace viscera::studio {
namespace {

QString q(const std::string& text) {
  return QString::fromStdString(text);
}

std::string model_bytes(const core::ModelDocument& model) {
  return core::model_to_json(model).dump(2) + "\n";
}

core::SceneObject& object_by_id(core::Scenario& scenario, const std::string& id) {
  for (auto& object : scenario.objects) {
    if (object.id == id) return object;
  }
  throw core::UsageError("the scenario has no object \"" + id + "\"");
}

}  // namespace

std::string model_file_path(const std::string& object_id) {
  return "models/" + object_id + ".viscera-model.json";
}

std::optional<core::ModelDocument> object_model(const PackageFiles& files,
                                                const std::string& object_id) {
  const auto file = files.find(model_file_path(object_id));
  if (file == files.end()) return std::nullopt;
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(file->second);
  } catch (const nlohmann::json::parse_error& e) {
    throw core::InputError(std::string("not JSON: ") + e.what(), {file->first, "", ""});
  }
  return core::model_from_json(json, file->first);
}

PackageFiles read_package_models(const std::filesystem::path& path,
                                 const core::Scenario& scenario) {
  PackageFiles files;
  if (std::filesystem::is_directory(path)) {
    for (const auto& object : scenario.objects) {
      const std::string relative = model_file_path(object.id);
      std::ifstream in(path / relative, std::ios::binary);
      if (!in) continue;
      files[relative].assign(std::istreambuf_iterator<char>(in), {});
    }
    return files;
  }
  const core::ZipLimits limits{core::kMaxZipEntryBytes, core::kMaxPackageBytes};
  const std::vector<std::string> entries = core::checked_zip_entries(path, limits);
  for (const auto& object : scenario.objects) {
    const std::string relative = model_file_path(object.id);
    if (std::find(entries.begin(), entries.end(), relative) != entries.end())
      files[relative] = core::read_zip_entry(path, relative, limits);
  }
  return files;
}

core::SceneObject build_studio_model_object(const core::ModelDocument& model,
                                            const std::string& fallback_material,
                                            core::Progress& progress) {
  core::SceneObject object = core::build_model_object(model, progress);
  if (!model.material) object.material = fallback_material;
  return object;
}

AddModelObjectCommand::AddModelObjectCommand(ScenarioDocument& document, core::ModelDocument model,
                                             core::SceneObject object,
                                             std::optional<core::Material> material)
    : document_(document), object_(std::move(object)), model_bytes_(model_bytes(model)) {
  if (document_.scenario().find_object(object_.id) != nullptr)
    throw core::UsageError("the scenario already has an object \"" + object_.id + "\"");
  if (material && !document_.scenario().materials.contains(material->id))
    material_ = std::move(material);
  setText(QObject::tr("Add model %1").arg(q(object_.name)));
}

void AddModelObjectCommand::redo() {
  auto& scenario = document_.edit_scenario();
  if (material_) scenario.materials[material_->id] = *material_;
  scenario.objects.push_back(object_);
  document_.edit_files()[model_file_path(object_.id)] = model_bytes_;
  if (material_) document_.notify_changed(ChangeKind::Materials, q(material_->id));
  document_.notify_changed(ChangeKind::Objects, q(object_.id));
}

void AddModelObjectCommand::undo() {
  auto& scenario = document_.edit_scenario();
  std::erase_if(scenario.objects, [&](const auto& o) { return o.id == object_.id; });
  document_.edit_files().erase(model_file_path(object_.id));
  if (material_) scenario.materials.erase(material_->id);
  document_.notify_changed(ChangeKind::Objects, q(object_.id));
  if (material_) document_.notify_changed(ChangeKind::Materials, q(material_->id));
}

MoveControlPointCommand::MoveControlPointCommand(ScenarioDocument& document,
                                                 const core::ModelDocument& moved,
                                                 core::SceneObject rebuilt, int index)
    : document_(document), new_object_(std::move(rebuilt)), new_model_(model_bytes(moved)) {
  const core::SceneObject* old = document_.scenario().find_object(moved.id);
  const auto file = document_.files().find(model_file_path(moved.id));
  if (old == nullptr || file == document_.files().end())
    throw core::UsageError("object \"" + moved.id + "\" is not a model object");
  old_object_ = *old;
  old_model_ = file->second;
  new_object_.material = old_object_.material;
  new_object_.texture = old_object_.texture;
  new_object_.group = old_object_.group;
  setText(QObject::tr("Move point %1 of %2").arg(index).arg(q(moved.id)));
}

void MoveControlPointCommand::set(const core::SceneObject& object, const std::string& model) {
  object_by_id(document_.edit_scenario(), object.id) = object;
  document_.edit_files()[model_file_path(object.id)] = model;
  document_.notify_changed(ChangeKind::Objects, q(object.id));
}

void MoveControlPointCommand::redo() {
  set(new_object_, new_model_);
}

void MoveControlPointCommand::undo() {
  set(old_object_, old_model_);
}

}  // namespace viscera::studio
