#include "studio/ui/pathology_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "studio/document/organ_commands.h"

namespace viscera::studio {

PathologyPanel::PathologyPanel(ScenarioDocument& document, QWidget* parent)
    : OrganPanel(document, parent) {
  auto* layout = new QVBoxLayout(this);
  object_label_ = new QLabel(this);
  object_label_->setWordWrap(true);
  layout->addWidget(object_label_);
  auto* form = new QFormLayout;
  kind_ = new QComboBox(this);
  kind_->addItem(tr("Polyp"), QStringLiteral("polyp"));
  kind_->addItem(tr("Submucosal myoma"), QStringLiteral("myoma-submucosal"));
  kind_->addItem(tr("Pedunculated myoma"), QStringLiteral("myoma-pedunculated"));
  kind_->addItem(tr("Intramural myoma"), QStringLiteral("myoma-intramural"));
  kind_->addItem(tr("Subserosal myoma"), QStringLiteral("myoma-subserosal"));
  kind_->setToolTip(
      tr("Polyps and submucosal or pedunculated myomas are seated on the cavity "
         "wall nearest to the click; subserosal myomas on the outer wall; an intramural "
         "myoma lies inside the wall beneath the click (the organ is re-meshed around it)"));
  form->addRow(tr("Kind"), kind_);
  size_mm_ = new QDoubleSpinBox(this);
  size_mm_->setRange(2.0, 60.0);
  size_mm_->setDecimals(1);
  size_mm_->setValue(8.0);
  size_mm_->setToolTip(tr("Myoma diameter or polyp length"));
  form->addRow(tr("Size (mm)"), size_mm_);
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 1'000'000'000);
  seed_->setValue(1);
  seed_->setToolTip(tr("Draws the lobes of a myoma and the lean of a stalk"));
  form->addRow(tr("Seed"), seed_);
  layout->addLayout(form);
  arm_ = new QPushButton(tr("Place by clicking on an organ"), this);
  arm_->setCheckable(true);
  layout->addWidget(arm_);
  layout->addStretch(1);
  refresh();
}

void PathologyPanel::set_choice(const QString& kind, double size) {
  kind_->setCurrentIndex(kind_->findData(kind));
  size_mm_->setValue(size * 1000.0);
}

bool PathologyPanel::armed() const {
  return arm_->isChecked();
}

void PathologyPanel::set_armed(bool armed) {
  arm_->setChecked(armed);
}

void PathologyPanel::refresh() {
  const core::SceneObject* object =
      object_id().isEmpty() ? nullptr : document_.scenario().find_object(object_id().toStdString());
  object_label_->setText(object == nullptr
                             ? tr("Arm placement, then click on an organ's wall in the 3D view.")
                             : tr("<b>%1</b> — %2 pathologies in the scenario")
                                   .arg(QString::fromStdString(object->name))
                                   .arg(document_.scenario().pathologies.size()));
}

void PathologyPanel::on_surface_clicked(const QString& id, const core::Vec3& point) {
  if (!armed()) return;
  const core::SceneObject* object = document_.scenario().find_object(id.toStdString());
  if (object == nullptr || object->role != core::ObjectRole::Organ) return;
  place_pathology_on(id, point, kind_->currentData().toString(), size_mm_->value() / 1000.0);
}

QString PathologyPanel::place_pathology_at(const core::Vec3& point, const QString& kind,
                                           double size) {
  const std::string host = require_object();
  if (host.empty()) return {};
  return place_pathology_on(QString::fromStdString(host), point, kind, size);
}

QString PathologyPanel::place_pathology_on(const QString& host, const core::Vec3& point,
                                           const QString& kind, double size) {
  PathologyParts parts;
  const core::Scenario& scenario = document_.scenario();
  const auto seed = static_cast<std::uint64_t>(seed_->value());
  if (!run(tr("Placing a %1").arg(kind), [&](core::Progress& progress) {
        parts = build_pathology_at(scenario, host.toStdString(), point, kind.toStdString(), size,
                                   seed, progress);
      }))
    return {};
  const QString id = QString::fromStdString(parts.record.id);
  if (!push([&] { return new AddPathologyCommand(document_, std::move(parts)); })) return {};
  emit placed(id);
  return id;
}

}  // namespace viscera::studio
