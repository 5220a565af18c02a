#include "studio/ui/template_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScreen>
#include <QScrollArea>
#include <QSpinBox>
#include <QStyle>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "studio/ui/clinical_units.h"
#include "templates/template_catalog.h"

namespace viscera::studio {
namespace {

QString group_title(templates::ParameterGroup group) {
  switch (group) {
    case templates::ParameterGroup::Anatomy:
      return QObject::tr("Anatomy");
    case templates::ParameterGroup::Pathologies:
      return QObject::tr("Pathologies");
    case templates::ParameterGroup::Tissue:
      return QObject::tr("Tissue");
    case templates::ParameterGroup::Vessels:
      return QObject::tr("Vessels");
    case templates::ParameterGroup::Texture:
      return QObject::tr("Texture");
    case templates::ParameterGroup::Meshing:
      return QObject::tr("Meshing");
  }
  return {};
}

}  // namespace

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
  scroll_ = new QScrollArea(this);
  scroll_->setWidgetResizable(true);
  scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  layout->addWidget(scroll_, 1);
  auto* seed_form = new QFormLayout;
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 2'000'000'000);
  seed_->setValue(1);
  seed_->setToolTip(tr("The same template, parameters and seed always give the same patient."));
  seed_form->addRow(tr("Seed"), seed_);
  layout->addLayout(seed_form);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  layout->addWidget(buttons_);
  connect(templates_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { show_parameters(); });
  show_parameters();
}

void TemplateDialog::show_parameters() {
  fields_.clear();
  auto* form = new QWidget;
  auto* column = new QVBoxLayout(form);
  if (templates_->currentIndex() >= 0) {
    const templates::ScenarioTemplate& t = templates::find_template(template_name());
    description_->setText(QString::fromStdString(t.description()));
    std::map<templates::ParameterGroup, QFormLayout*> groups;
    const auto parameters = t.parameters();
    for (const auto& p : parameters)
      groups[templates::parameter_group(p)] = nullptr;
    for (auto& [group, rows] : groups) {
      auto* box = new QGroupBox(group_title(group), form);
      rows = new QFormLayout(box);
      rows->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
      column->addWidget(box);
    }
    for (const auto& p : parameters) {
      const ClinicalUnit unit = clinical_unit(p.unit);
      Field field;
      field.scale = unit.scale;
      field.minimum = p.minimum;
      field.maximum = p.maximum;
      field.integer = p.integer;
      field.editor = new QDoubleSpinBox(form);
      const auto magnitude = [&](double v) { return std::abs(v * unit.scale); };
      double smallest = std::max(magnitude(p.maximum), magnitude(p.default_value));
      for (const double v : {p.minimum, p.maximum, p.default_value})
        if (magnitude(v) > 0.0) smallest = std::min(smallest, magnitude(v));
      field.editor->setDecimals(p.integer ? 0 : display_decimals(smallest));
      field.editor->setRange(p.minimum * unit.scale, p.maximum * unit.scale);
      field.editor->setSuffix(unit.suffix);
      field.editor->setValue(p.default_value * unit.scale);
      field.editor->setSingleStep(p.integer ? 1.0 : std::pow(10.0, 1 - field.editor->decimals()));
      field.shown_default = field.editor->value();
      const QString range = tr("%1 to %2%3")
                                .arg(p.minimum * unit.scale, 0, 'g', 4)
                                .arg(p.maximum * unit.scale, 0, 'g', 4)
                                .arg(unit.suffix);
      const QString description = QString::fromStdString(p.description);
      field.editor->setToolTip(tr("%1 (%2)").arg(description, range));
      auto* cell = new QWidget(form);
      auto* stack = new QVBoxLayout(cell);
      stack->setContentsMargins(0, 0, 0, 0);
      stack->setSpacing(1);
      stack->addWidget(field.editor);
      auto* help = new QLabel(tr("%1 · %2").arg(description, range), cell);
      help->setStyleSheet(QStringLiteral("color: palette(mid); font-size: small;"));
      help->setToolTip(description);
      stack->addWidget(help);
      auto* label = new QLabel(readable_name(p.name), form);
      label->setBuddy(field.editor);
      label->setToolTip(description);
      groups.at(templates::parameter_group(p))->addRow(label, cell);
      fields_[p.name] = field;
    }
  }
  column->addStretch(1);
  scroll_->setWidget(form);  // deletes the previous form
  scroll_->setMinimumWidth(form->sizeHint().width() +
                           style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 4);
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

QDoubleSpinBox* TemplateDialog::editor(const std::string& name) const {
  const auto field = fields_.find(name);
  return field == fields_.end() ? nullptr : field->second.editor;
}

bool TemplateDialog::set_parameter(const std::string& name, double value) {
  const auto field = fields_.find(name);
  if (field == fields_.end()) return false;
  field->second.editor->setValue(value * field->second.scale);
  return true;
}

std::map<std::string, std::string> TemplateDialog::overrides() const {
  std::map<std::string, std::string> values;
  for (const auto& [name, field] : fields_) {
    if (field.editor->value() == field.shown_default) continue;
    // The shown range is rounded to the editor's decimals: keep the SI value inside the
    // catalogue's range.
    double value = std::clamp(field.editor->value() / field.scale, field.minimum, field.maximum);
    if (field.integer) value = std::round(value);
    values[name] = QString::number(value, 'g', 12).toStdString();
  }
  return values;
}

std::uint64_t TemplateDialog::seed() const {
  return static_cast<std::uint64_t>(seed_->value());
}
void TemplateDialog::set_seed(std::uint64_t seed) {
  seed_->setValue(static_cast<int>(seed));
}

void TemplateDialog::fit_to(const QRect& available) {
  // The window frame (title bar) is not part of the widget's height.
  const int frame = std::max(frameGeometry().height() - geometry().height(), 32);
  const int max_height = std::max(240, available.height() - frame);
  const int max_width = std::max(320, available.width());
  setMaximumSize(max_width, max_height);
  const QSize wanted = sizeHint();
  const int inner = scroll_->widget() != nullptr ? scroll_->widget()->sizeHint().height() : 0;
  // As tall as the whole form when it fits, else the screen's height; the form then scrolls.
  const int height = std::min(max_height, wanted.height() - scroll_->sizeHint().height() + inner +
                                              2 * scroll_->frameWidth());
  resize(std::min(max_width, wanted.width()), std::max(height, minimumSizeHint().height()));
  if (!available.contains(frameGeometry()))
    move(available.x() + (available.width() - frameGeometry().width()) / 2,
         available.y() + std::max(0, (available.height() - frameGeometry().height()) / 2));
}

void TemplateDialog::showEvent(QShowEvent* event) {
  QDialog::showEvent(event);
  if (const QScreen* s = screen()) fit_to(s->availableGeometry());
}

}  // namespace viscera::studio
