#include "studio/ui/template_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "templates/template_catalog.h"

namespace viscera::studio {

TemplateDialog::TemplateDialog(QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("New from template"));
  auto* layout = new QVBoxLayout(this);
  templates_ = new QComboBox(this);
  for (const auto& t : templates::template_catalog()) {
    templates_->addItem(QString::fromStdString(t->name()));
  }
  layout->addWidget(templates_);
  description_ = new QLabel(this);
  description_->setWordWrap(true);
  layout->addWidget(description_);
  form_ = new QFormLayout;
  layout->addLayout(form_);
  auto* seed_form = new QFormLayout;
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 2'000'000'000);
  seed_->setValue(1);
  seed_form->addRow(tr("Seed"), seed_);
  layout->addLayout(seed_form);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  layout->addWidget(buttons);
  connect(templates_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { show_parameters(); });
  show_parameters();
}

void TemplateDialog::show_parameters() {
  while (form_->rowCount() > 0)
    form_->removeRow(0);
  editors_.clear();
  defaults_.clear();
  if (templates_->currentIndex() < 0) return;
  const templates::ScenarioTemplate& t = templates::find_template(template_name());
  description_->setText(QString::fromStdString(t.description()));
  for (const auto& p : t.parameters()) {
    auto* editor = new QDoubleSpinBox(this);
    // Enough decimals for the smallest of the range's magnitudes (metres need ~4).
    const double smallest =
        std::max(1e-9, std::min(std::abs(p.minimum) > 0 ? std::abs(p.minimum) : std::abs(p.maximum),
                                std::abs(p.default_value) > 0 ? std::abs(p.default_value) : 1.0));
    const int decimals =
        p.integer ? 0 : std::clamp(3 - static_cast<int>(std::floor(std::log10(smallest))), 1, 9);
    editor->setDecimals(decimals);
    editor->setRange(p.minimum, p.maximum);
    editor->setValue(p.default_value);
    editor->setSingleStep(p.integer ? 1.0 : std::pow(10.0, -decimals + 1));
    editor->setToolTip(QString::fromStdString(p.description));
    form_->addRow(QString::fromStdString(p.name + " (" + p.unit + ")"), editor);
    editors_[p.name] = editor;
    defaults_[p.name] = p.default_value;
  }
}

bool TemplateDialog::select_template(const std::string& name) {
  const int index = templates_->findText(QString::fromStdString(name));
  if (index < 0) return false;
  templates_->setCurrentIndex(index);
  return true;
}

std::string TemplateDialog::template_name() const {
  return templates_->currentText().toStdString();
}

bool TemplateDialog::set_parameter(const std::string& name, double value) {
  const auto editor = editors_.find(name);
  if (editor == editors_.end()) return false;
  editor->second->setValue(value);
  return true;
}

std::map<std::string, std::string> TemplateDialog::overrides() const {
  std::map<std::string, std::string> values;
  for (const auto& [name, editor] : editors_) {
    if (std::abs(editor->value() - defaults_.at(name)) >
        0.5 * std::pow(10.0, -editor->decimals())) {
      values[name] = QString::number(editor->value(), 'g', 12).toStdString();
    }
  }
  return values;
}

std::uint64_t TemplateDialog::seed() const {
  return static_cast<std::uint64_t>(seed_->value());
}
void TemplateDialog::set_seed(std::uint64_t seed) {
  seed_->setValue(static_cast<int>(seed));
}

}  // namespace viscera::studio
