#include "studio/ui/material_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

#include "core/error.h"
#include "core/materials/shipped_materials.h"

namespace viscera::studio {
namespace {

constexpr MaterialField kFields[] = {
    MaterialField::Density,         MaterialField::DistanceStiffness,
    MaterialField::AreaStiffness,   MaterialField::VolumeStiffness,
    MaterialField::DistanceDamping, MaterialField::TearingThreshold,
    MaterialField::PlasticYield};

QString q(const std::string& text) {
  return QString::fromStdString(text);
}

}  // namespace

MaterialPanel::MaterialPanel(ScenarioDocument& document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  object_label_ = new QLabel(this);
  object_label_->setWordWrap(true);
  layout->addWidget(object_label_);
  // Hidden with nothing selected: a material that belongs to nothing, with zeros that look like
  // data, would mislead (issue 23 §6).
  editors_box_ = new QWidget(this);
  auto* form = new QFormLayout(editors_box_);
  form->setContentsMargins(0, 0, 0, 0);
  picker_ = new QComboBox(this);
  form->addRow(tr("Material"), picker_);
  for (const MaterialField field : kFields) {
    auto* editor = new QDoubleSpinBox(this);
    editor->setRange(0.0, 1.0e9);
    const bool strain =
        field == MaterialField::TearingThreshold || field == MaterialField::PlasticYield;
    editor->setDecimals(strain ? 3 : 1);
    editor->setSingleStep(strain ? 0.01 : 10.0);
    editor->setKeyboardTracking(false);
    form->addRow(material_field_label(field), editor);
    editors_[field] = editor;
    connect(editor, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            [this, field](double value) {
              if (!updating_) edit_field(field, value);
            });
  }
  layout->addWidget(editors_box_);
  source_label_ = new QLabel(this);
  source_label_->setWordWrap(true);
  layout->addWidget(source_label_);
  layout->addStretch(1);

  connect(picker_, qOverload<int>(&QComboBox::activated), this,
          [this](int index) { choose_material(picker_->itemData(index).toString()); });
  connect(&document_, &ScenarioDocument::changed, this, [this] { refresh(); });
  show_object({});
}

void MaterialPanel::show_object(const QString& id) {
  object_id_ = id;
  refresh();
}

void MaterialPanel::refresh() {
  updating_ = true;
  const core::SceneObject* object =
      object_id_.isEmpty() ? nullptr : document_.scenario().find_object(object_id_.toStdString());
  if (object == nullptr) object_id_.clear();
  setEnabled(object != nullptr);
  editors_box_->setVisible(object != nullptr);
  object_label_->setText(object == nullptr ? tr("Select an object to see and edit its material.")
                                           : tr("<b>%1</b>").arg(q(object->name)));
  picker_->clear();
  const auto& materials = document_.scenario().materials;
  for (const auto& [id, material] : materials) {
    picker_->addItem(tr("%1 (scenario)").arg(q(material.name)), q(id));
  }
  for (const auto& shipped : core::shipped_materials()) {
    if (materials.contains(shipped.material.id)) continue;
    picker_->addItem(tr("%1 (library)").arg(q(shipped.material.name)), q(shipped.material.id));
  }
  const core::Material* material = nullptr;
  if (object != nullptr) {
    const auto it = materials.find(object->material);
    if (it != materials.end()) material = &it->second;
    picker_->setCurrentIndex(picker_->findData(q(object->material)));
  }
  for (const auto& [field, editor] : editors_) {
    editor->setEnabled(material != nullptr);
    editor->setValue(material != nullptr ? material_field(*material, field) : 0.0);
  }
  source_label_->setText(material != nullptr && !material->source.empty()
                             ? tr("Source: %1").arg(q(material->source))
                             : QString());
  updating_ = false;
}

void MaterialPanel::push(QUndoCommand* command) {
  document_.undo_stack()->push(command);
}

bool MaterialPanel::choose_material(const QString& material_id) {
  if (object_id_.isEmpty() || material_id.isEmpty()) return false;
  const std::string id = material_id.toStdString();
  const auto& materials = document_.scenario().materials;
  core::Material material;
  if (const auto it = materials.find(id); it != materials.end()) {
    material = it->second;
  } else if (const core::ShippedMaterial* shipped = core::find_shipped_material(id)) {
    material = shipped->material;
  } else {
    return false;
  }
  const core::SceneObject* object = document_.scenario().find_object(object_id_.toStdString());
  if (object != nullptr && object->material == id) return true;
  push(new AssignMaterialCommand(document_, object_id_.toStdString(), material));
  return true;
}

bool MaterialPanel::edit_field(MaterialField field, double value) {
  const core::SceneObject* object =
      object_id_.isEmpty() ? nullptr : document_.scenario().find_object(object_id_.toStdString());
  if (object == nullptr || object->material.empty()) return false;
  try {
    const auto& material = document_.scenario().materials.at(object->material);
    if (material_field(material, field) == value) return true;
    push(new EditMaterialCommand(document_, object->material, field, value));
    return true;
  } catch (const std::exception& e) {
    emit edit_failed(QString::fromUtf8(e.what()));
    refresh();
    return false;
  }
}

}  // namespace viscera::studio
