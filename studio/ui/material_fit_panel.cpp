#include "studio/ui/material_fit_panel.h"

#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "core/error.h"
#include "core/materials/material_constants.h"
#include "core/materials/stress_strain_csv.h"
#include "studio/document/organ_commands.h"
#include "studio/ui/stress_strain_plot.h"

namespace viscera::studio {

MaterialFitPanel::MaterialFitPanel(ScenarioDocument& document, QWidget* parent)
    : OrganPanel(document, parent) {
  auto* layout = new QVBoxLayout(this);
  object_label_ = new QLabel(this);
  object_label_->setWordWrap(true);
  layout->addWidget(object_label_);
  plot_ = new StressStrainPlot(this);
  layout->addWidget(plot_, 2);
  fit_label_ = new QLabel(this);
  fit_label_->setWordWrap(true);
  fit_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(fit_label_);
  table_ = new QTableWidget(0, 2, this);
  table_->setHorizontalHeaderLabels({tr("strain"), tr("stress (Pa)")});
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  layout->addWidget(table_, 1);
  auto* form = new QFormLayout;
  poisson_ = new QDoubleSpinBox(this);
  poisson_->setRange(0.25, 0.499);
  poisson_->setDecimals(3);
  poisson_->setSingleStep(0.01);
  poisson_->setValue(0.45);
  form->addRow(tr("Poisson ratio ν"), poisson_);
  layout->addLayout(form);
  auto* buttons = new QHBoxLayout;
  auto* load = new QPushButton(tr("Load CSV…"), this);
  auto* add = new QPushButton(tr("Add row"), this);
  apply_ = new QPushButton(tr("Apply to material"), this);
  buttons->addWidget(load);
  buttons->addWidget(add);
  buttons->addWidget(apply_);
  layout->addLayout(buttons);

  connect(load, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Stress–strain samples"), QString(),
                                                      tr("CSV (*.csv *.txt);;All files (*)"));
    if (!path.isEmpty()) load_csv(path.toStdString());
  });
  connect(add, &QPushButton::clicked, this, [this] {
    updating_ = true;
    const int row = table_->rowCount();
    table_->insertRow(row);
    table_->setItem(row, 0, new QTableWidgetItem(QStringLiteral("0")));
    table_->setItem(row, 1, new QTableWidgetItem(QStringLiteral("0")));
    updating_ = false;
    refit();
  });
  connect(apply_, &QPushButton::clicked, this, [this] { apply_fit(); });
  connect(table_, &QTableWidget::itemChanged, this, [this] {
    if (!updating_) refit();
  });
  refresh();
  refit();
}

bool MaterialFitPanel::load_csv(const std::filesystem::path& path) {
  try {
    const core::StressStrainCurve curve = core::read_stress_strain_csv(path);
    set_samples(curve.strain, curve.stress);
    return true;
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return false;
  }
}

void MaterialFitPanel::set_samples(const std::vector<double>& strain,
                                   const std::vector<double>& stress) {
  updating_ = true;
  const std::size_t rows = std::min(strain.size(), stress.size());
  table_->setRowCount(static_cast<int>(rows));
  for (std::size_t i = 0; i < rows; ++i) {
    table_->setItem(static_cast<int>(i), 0,
                    new QTableWidgetItem(QString::number(strain[i], 'g', 17)));
    table_->setItem(static_cast<int>(i), 1,
                    new QTableWidgetItem(QString::number(stress[i], 'g', 17)));
  }
  updating_ = false;
  refit();
}

void MaterialFitPanel::edit_sample(int row, int column, double value) {
  if (QTableWidgetItem* item = table_->item(row, column)) {
    item->setText(QString::number(value, 'g', 17));  // itemChanged refits
  }
}

core::StressStrainCurve MaterialFitPanel::samples() const {
  core::StressStrainCurve curve;
  for (int row = 0; row < table_->rowCount(); ++row) {
    bool strain_ok = false, stress_ok = false;
    const double strain =
        table_->item(row, 0) ? table_->item(row, 0)->text().toDouble(&strain_ok) : 0.0;
    const double stress =
        table_->item(row, 1) ? table_->item(row, 1)->text().toDouble(&stress_ok) : 0.0;
    if (!strain_ok || !stress_ok) continue;  // a cell being typed
    curve.strain.push_back(strain);
    curve.stress.push_back(stress);
  }
  return curve;
}

void MaterialFitPanel::refit() {
  const core::StressStrainCurve curve = samples();
  fit_.reset();
  fit_error_.clear();
  try {
    fit_ = core::fit_cubic_stress(curve);
  } catch (const core::Error& e) {
    fit_error_ = QString::fromUtf8(e.what());
  }
  plot_->set_data(curve.strain, curve.stress,
                  fit_ ? std::optional<std::array<double, 4>>(fit_->cubic) : std::nullopt);
  if (fit_) {
    fit_label_->setText(tr("σ(ε) = %1 ε + %2 ε|ε| + %3 ε³ Pa\nRMS error %4 Pa, R² %5")
                            .arg(fit_->cubic[1], 0, 'g', 5)
                            .arg(fit_->cubic[2], 0, 'g', 5)
                            .arg(fit_->cubic[3], 0, 'g', 5)
                            .arg(fit_->rms_error, 0, 'g', 3)
                            .arg(fit_->r_squared, 0, 'f', 4));
  } else {
    fit_label_->setText(curve.strain.empty() ? tr("Load or type at least 4 samples.") : fit_error_);
  }
  refresh();
}

void MaterialFitPanel::refresh() {
  const core::SceneObject* object =
      object_id().isEmpty() ? nullptr : document_.scenario().find_object(object_id().toStdString());
  const bool has_material =
      object != nullptr && document_.scenario().materials.contains(object->material);
  apply_->setEnabled(has_material && fit_.has_value());
  object_label_->setText(object == nullptr ? tr("Select an object to fit its material.")
                                           : tr("<b>%1</b> — material %2")
                                                 .arg(QString::fromStdString(object->name),
                                                      QString::fromStdString(object->material)));
}

bool MaterialFitPanel::apply_fit() {
  const std::string id = require_object();
  if (id.empty()) return false;
  const core::SceneObject* object = document_.scenario().find_object(id);
  const auto material = document_.scenario().materials.find(object->material);
  if (material == document_.scenario().materials.end()) {
    emit failed(tr("Object %1 has no scenario material to fit.").arg(QString::fromStdString(id)));
    return false;
  }
  if (!fit_) {
    emit failed(fit_error_.isEmpty() ? tr("There is no fit to apply.") : fit_error_);
    return false;
  }
  core::Material fitted;
  try {
    core::ElasticityOptions elasticity;
    elasticity.poisson_ratio = poisson_->value();
    const core::StressStrainCurve curve = samples();
    fitted = core::material_from_measured_curve(curve, elasticity, material->second);
    fitted.source = "cubic fitted in the studio to " + std::to_string(curve.strain.size()) +
                    " samples (RMS error " + std::to_string(fit_->rms_error) +
                    " Pa), Poisson ratio " + std::to_string(elasticity.poisson_ratio);
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return false;
  }
  return push([&] { return new ReplaceMaterialCommand(document_, std::move(fitted)); });
}

}  // namespace viscera::studio
