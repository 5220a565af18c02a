#include "studio/ui/vessel_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "studio/document/organ_commands.h"

namespace viscera::studio {

VesselPanel::VesselPanel(ScenarioDocument& document, QWidget* parent)
    : OrganPanel(document, parent) {
  auto* layout = new QVBoxLayout(this);
  object_label_ = new QLabel(this);
  object_label_->setWordWrap(true);
  layout->addWidget(object_label_);
  auto* form = new QFormLayout;
  method_ = new QComboBox(this);
  method_->addItem(tr("CCO (constrained constructive optimisation)"),
                   static_cast<int>(VesselMethod::Cco));
  method_->addItem(tr("L-system (built-in grammar)"), static_cast<int>(VesselMethod::Lsystem));
  form->addRow(tr("Method"), method_);
  terminals_ = new QSpinBox(this);
  terminals_->setRange(2, 5000);
  terminals_->setValue(60);
  form->addRow(tr("Terminal segments"), terminals_);
  generations_ = new QSpinBox(this);
  generations_->setRange(1, 10);
  generations_->setValue(5);
  form->addRow(tr("Generations"), generations_);
  root_radius_mm_ = new QDoubleSpinBox(this);
  root_radius_mm_->setRange(0.05, 20.0);
  root_radius_mm_->setDecimals(2);
  root_radius_mm_->setValue(1.5);
  form->addRow(tr("Root radius (mm)"), root_radius_mm_);
  murray_ = new QDoubleSpinBox(this);
  murray_->setRange(2.0, 3.5);
  murray_->setDecimals(2);
  murray_->setSingleStep(0.05);
  murray_->setValue(3.0);
  form->addRow(tr("Murray exponent γ"), murray_);
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 1'000'000'000);
  seed_->setValue(1);
  form->addRow(tr("Seed"), seed_);
  layout->addLayout(form);
  generate_ = new QPushButton(tr("Grow vessels in the selected organ"), this);
  layout->addWidget(generate_);
  layout->addStretch(1);
  connect(method_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          &VesselPanel::update_enabled);
  connect(generate_, &QPushButton::clicked, this, [this] { generate(); });
  update_enabled();
  refresh();
}

VesselRequest VesselPanel::request() const {
  VesselRequest r;
  r.method = static_cast<VesselMethod>(method_->currentData().toInt());
  r.terminals = terminals_->value();
  r.generations = generations_->value();
  r.root_radius = root_radius_mm_->value() / 1000.0;
  r.murray_exponent = murray_->value();
  r.seed = static_cast<std::uint64_t>(seed_->value());
  return r;
}

void VesselPanel::set_request(const VesselRequest& r) {
  method_->setCurrentIndex(method_->findData(static_cast<int>(r.method)));
  terminals_->setValue(r.terminals);
  generations_->setValue(r.generations);
  root_radius_mm_->setValue(r.root_radius * 1000.0);
  murray_->setValue(r.murray_exponent);
  seed_->setValue(static_cast<int>(r.seed));
}

void VesselPanel::update_enabled() {
  // As the CLI: CCO radii follow from Poiseuille flow and Murray's law, the L-system's from
  // the root radius and r ∝ Q^(1/3).
  const bool cco = method_->currentData().toInt() == static_cast<int>(VesselMethod::Cco);
  terminals_->setEnabled(cco);
  murray_->setEnabled(cco);
  generations_->setEnabled(!cco);
  root_radius_mm_->setEnabled(!cco);
}

void VesselPanel::refresh() {
  const core::SceneObject* object =
      object_id().isEmpty() ? nullptr : document_.scenario().find_object(object_id().toStdString());
  generate_->setEnabled(object != nullptr);
  int trees = 0;
  for (const auto& tree : document_.scenario().vessel_trees)
    trees += object != nullptr && tree.host_object == object->id ? 1 : 0;
  object_label_->setText(object == nullptr ? tr("Select an organ to grow vessels in it.")
                                           : tr("<b>%1</b> — %n vessel tree(s)", nullptr, trees)
                                                 .arg(QString::fromStdString(object->name)));
}

bool VesselPanel::generate() {
  return generate_vessels(request());
}

bool VesselPanel::generate_vessels(const VesselRequest& request) {
  const std::string id = require_object();
  if (id.empty()) return false;
  core::VesselTree tree;
  const core::Scenario& scenario = document_.scenario();
  if (!run(tr("Growing vessels in %1").arg(QString::fromStdString(id)),
           [&](core::Progress& progress) {
             tree = grow_organ_vessels(scenario, id, request, progress);
           }))
    return false;
  return push([&] { return new AddVesselTreeCommand(document_, std::move(tree)); });
}

}  // namespace viscera::studio
