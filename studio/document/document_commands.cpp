#include "studio/document/document_commands.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::studio {
namespace {

core::SceneObject& object_by_id(core::Scenario& scenario, const std::string& id) {
  for (auto& object : scenario.objects) {
    if (object.id == id) return object;
  }
  throw core::UsageError("the scenario has no object \"" + id + "\"");
}

QString q(const std::string& text) {
  return QString::fromStdString(text);
}

}  // namespace

AddObjectCommand::AddObjectCommand(ScenarioDocument& document, core::SceneObject object,
                                   std::optional<core::Material> material)
    : document_(document), object_(std::move(object)) {
  if (document_.scenario().find_object(object_.id) != nullptr) {
    throw core::UsageError("the scenario already has an object \"" + object_.id + "\"");
  }
  if (material && !document_.scenario().materials.contains(material->id)) {
    added_material_ = std::move(material);
  }
  setText(QObject::tr("Create %1").arg(q(object_.name)));
}

void AddObjectCommand::redo() {
  auto& scenario = document_.edit_scenario();
  if (added_material_) scenario.materials[added_material_->id] = *added_material_;
  scenario.objects.push_back(object_);
  if (added_material_) document_.notify_changed(ChangeKind::Materials, q(added_material_->id));
  document_.notify_changed(ChangeKind::Objects, q(object_.id));
}

void AddObjectCommand::undo() {
  auto& scenario = document_.edit_scenario();
  std::erase_if(scenario.objects, [&](const auto& o) { return o.id == object_.id; });
  if (added_material_) scenario.materials.erase(added_material_->id);
  document_.notify_changed(ChangeKind::Objects, q(object_.id));
  if (added_material_) document_.notify_changed(ChangeKind::Materials, q(added_material_->id));
}

RemoveObjectCommand::RemoveObjectCommand(ScenarioDocument& document, const std::string& object_id)
    : document_(document) {
  const auto& scenario = document_.scenario();
  const auto it = std::find_if(scenario.objects.begin(), scenario.objects.end(),
                               [&](const auto& o) { return o.id == object_id; });
  if (it == scenario.objects.end()) {
    throw core::UsageError("the scenario has no object \"" + object_id + "\"");
  }
  for (const auto& pathology : scenario.pathologies) {
    if (pathology.host_object == object_id || pathology.object == object_id) {
      throw core::UsageError("object \"" + object_id + "\" is used by pathology \"" + pathology.id +
                             "\"");
    }
  }
  for (const auto& connection : scenario.connections) {
    if (connection.object_a == object_id || connection.object_b == object_id) {
      throw core::UsageError("object \"" + object_id + "\" is used by connection \"" +
                             connection.id + "\"");
    }
  }
  for (const auto& tree : scenario.vessel_trees) {
    if (tree.host_object == object_id) {
      throw core::UsageError("object \"" + object_id + "\" hosts vessel tree \"" + tree.id + "\"");
    }
  }
  for (const auto& deformation : scenario.active_deformations) {
    if (deformation.target_object == object_id) {
      throw core::UsageError("object \"" + object_id + "\" is moved by \"" + deformation.id + "\"");
    }
  }
  object_ = *it;
  index_ = static_cast<std::size_t>(it - scenario.objects.begin());
  setText(QObject::tr("Delete %1").arg(q(object_.name)));
}

void RemoveObjectCommand::redo() {
  auto& objects = document_.edit_scenario().objects;
  objects.erase(objects.begin() + static_cast<std::ptrdiff_t>(index_));
  document_.notify_changed(ChangeKind::Objects, q(object_.id));
}

void RemoveObjectCommand::undo() {
  auto& objects = document_.edit_scenario().objects;
  objects.insert(objects.begin() + static_cast<std::ptrdiff_t>(index_), object_);
  document_.notify_changed(ChangeKind::Objects, q(object_.id));
}

AssignMaterialCommand::AssignMaterialCommand(ScenarioDocument& document,
                                             const std::string& object_id,
                                             const core::Material& material)
    : document_(document), object_id_(object_id), material_(material) {
  const core::SceneObject* object = document_.scenario().find_object(object_id);
  if (object == nullptr) throw core::UsageError("the scenario has no object \"" + object_id + "\"");
  old_material_ = object->material;
  adds_material_ = !document_.scenario().materials.contains(material.id);
  setText(QObject::tr("Material of %1: %2").arg(q(object->name), q(material.name)));
}

void AssignMaterialCommand::redo() {
  auto& scenario = document_.edit_scenario();
  if (adds_material_) scenario.materials[material_.id] = material_;
  object_by_id(scenario, object_id_).material = material_.id;
  if (adds_material_) document_.notify_changed(ChangeKind::Materials, q(material_.id));
  document_.notify_changed(ChangeKind::Objects, q(object_id_));
}

void AssignMaterialCommand::undo() {
  auto& scenario = document_.edit_scenario();
  object_by_id(scenario, object_id_).material = old_material_;
  if (adds_material_) scenario.materials.erase(material_.id);
  if (adds_material_) document_.notify_changed(ChangeKind::Materials, q(material_.id));
  document_.notify_changed(ChangeKind::Objects, q(object_id_));
}

QString material_field_label(MaterialField field) {
  switch (field) {
    case MaterialField::Density:
      return QObject::tr("density (kg/m³)");
    case MaterialField::DistanceStiffness:
      return QObject::tr("distance stiffness (Pa)");
    case MaterialField::AreaStiffness:
      return QObject::tr("area stiffness (N/m)");
    case MaterialField::VolumeStiffness:
      return QObject::tr("volume stiffness (Pa)");
    case MaterialField::DistanceDamping:
      return QObject::tr("distance damping (Pa·s)");
    case MaterialField::TearingThreshold:
      return QObject::tr("tearing threshold (strain)");
    case MaterialField::PlasticYield:
      return QObject::tr("plastic yield (strain)");
  }
  return {};
}

double material_field(const core::Material& m, MaterialField field) {
  switch (field) {
    case MaterialField::Density:
      return m.density;
    case MaterialField::DistanceStiffness:
      return m.distance_stiffness;
    case MaterialField::AreaStiffness:
      return m.area_stiffness;
    case MaterialField::VolumeStiffness:
      return m.volume_stiffness;
    case MaterialField::DistanceDamping:
      return m.distance_damping;
    case MaterialField::TearingThreshold:
      return m.tearing_threshold;
    case MaterialField::PlasticYield:
      return m.plastic_yield;
  }
  return 0.0;
}

void set_material_field(core::Material& m, MaterialField field, double value) {
  switch (field) {
    case MaterialField::Density:
      m.density = value;
      break;
    case MaterialField::DistanceStiffness:
      m.distance_stiffness = value;
      break;
    case MaterialField::AreaStiffness:
      m.area_stiffness = value;
      break;
    case MaterialField::VolumeStiffness:
      m.volume_stiffness = value;
      break;
    case MaterialField::DistanceDamping:
      m.distance_damping = value;
      break;
    case MaterialField::TearingThreshold:
      m.tearing_threshold = value;
      break;
    case MaterialField::PlasticYield:
      m.plastic_yield = value;
      break;
  }
}

EditMaterialCommand::EditMaterialCommand(ScenarioDocument& document, const std::string& material_id,
                                         MaterialField field, double value)
    : document_(document), material_id_(material_id), field_(field), new_value_(value) {
  const auto it = document_.scenario().materials.find(material_id);
  if (it == document_.scenario().materials.end()) {
    throw core::UsageError("the scenario has no material \"" + material_id + "\"");
  }
  if (!std::isfinite(value) || value < 0.0) {
    throw core::UsageError(material_field_label(field).toStdString() + " of \"" + material_id +
                           "\" must be a finite value ≥ 0");
  }
  old_value_ = material_field(it->second, field);
  setText(QObject::tr("%1 of %2").arg(material_field_label(field), q(it->second.name)));
}

void EditMaterialCommand::apply(double value) {
  set_material_field(document_.edit_scenario().materials.at(material_id_), field_, value);
  document_.notify_changed(ChangeKind::Materials, q(material_id_));
}

void EditMaterialCommand::redo() {
  apply(new_value_);
}
void EditMaterialCommand::undo() {
  apply(old_value_);
}

bool EditMaterialCommand::mergeWith(const QUndoCommand* other) {
  const auto* edit = dynamic_cast<const EditMaterialCommand*>(other);
  if (edit == nullptr || edit->material_id_ != material_id_ || edit->field_ != field_) return false;
  new_value_ = edit->new_value_;
  return true;
}

}  // namespace viscera::studio
