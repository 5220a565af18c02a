#include "studio/ui/variants_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QSpinBox>

namespace viscera::studio {

VariantsDialog::VariantsDialog(const core::Scenario& scenario, QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Generate variants"));
  source_ = new QComboBox(this);
  if (has_template_source(scenario)) {
    source_->addItem(tr("Template %1: its variability rules")
                         .arg(QString::fromStdString(scenario.provenance.template_name)),
                     static_cast<int>(VariantSource::Template));
  }
  source_->addItem(tr("This scenario: smooth shape deformation, pathology sizes"),
                   static_cast<int>(VariantSource::Scenario));
  count_ = new QSpinBox(this);
  count_->setRange(1, 256);
  count_->setValue(8);
  seed_ = new QLineEdit(QStringLiteral("1"), this);
  seed_->setValidator(
      new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[0-9]{1,19}")), this));
  attempts_ = new QSpinBox(this);
  attempts_->setRange(1, 100);
  attempts_->setValue(5);
  simulate_ = new QCheckBox(tr("Also simulate one second of each variant"), this);

  auto* form = new QFormLayout(this);
  form->addRow(tr("Vary"), source_);
  form->addRow(tr("Number of variants"), count_);
  form->addRow(tr("Seed"), seed_);
  form->addRow(tr("Draws per variant"), attempts_);
  form->addRow(simulate_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

VariantRequest VariantsDialog::request() const {
  VariantRequest request;
  request.source = static_cast<VariantSource>(source_->currentData().toInt());
  request.count = count_->value();
  request.seed = seed_->text().toULongLong();
  request.max_attempts = attempts_->value();
  request.simulate = simulate_->isChecked();
  return request;
}

}  // namespace viscera::studio
