#include "studio/ui/training_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace viscera::studio {

TrainingDialog::TrainingDialog(QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Launch training"));
  auto* form = new QFormLayout(this);
  kind_ = new QComboBox(this);
  kind_->addItem(tr("Keyboard and mouse"), static_cast<int>(TrainingInput::Kind::Keyboard));
  kind_->addItem(tr("Gamepad"), static_cast<int>(TrainingInput::Kind::Gamepad));
  kind_->addItem(tr("Haptic device over UDP"), static_cast<int>(TrainingInput::Kind::Device));
  kind_->addItem(tr("Script"), static_cast<int>(TrainingInput::Kind::Script));
  form->addRow(tr("Instrument driven by"), kind_);

  port_ = new QSpinBox(this);
  port_->setRange(0, 65535);
  port_->setValue(5005);
  port_->setToolTip(tr("The device sends its pose packets to 127.0.0.1 on this port"));
  form->addRow(tr("UDP port"), port_);

  script_row_ = new QWidget(this);
  auto* script_layout = new QHBoxLayout(script_row_);
  script_layout->setContentsMargins(0, 0, 0, 0);
  script_ = new QLineEdit(script_row_);
  script_->setPlaceholderText(tr("viscera-script JSON"));
  auto* browse = new QPushButton(tr("Browse…"), script_row_);
  script_layout->addWidget(script_);
  script_layout->addWidget(browse);
  form->addRow(tr("Script"), script_row_);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Script"), QString(),
                                                      tr("Scripts (*.json);;All files (*)"));
    if (!path.isEmpty()) script_->setText(path);
  });

  duration_ = new QDoubleSpinBox(this);
  duration_->setRange(0.0, 3600.0);
  duration_->setDecimals(1);
  duration_->setSuffix(tr(" s"));
  duration_->setSpecialValueText(tr("the scenario's limit"));
  duration_->setValue(0.0);
  form->addRow(tr("Session length"), duration_);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText(tr("Launch"));
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(kind_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { show_input_fields(); });
  show_input_fields();
}

void TrainingDialog::show_input_fields() {
  const auto kind = static_cast<TrainingInput::Kind>(kind_->currentData().toInt());
  port_->setEnabled(kind == TrainingInput::Kind::Device);
  script_row_->setEnabled(kind == TrainingInput::Kind::Script);
}

TrainingInput TrainingDialog::input() const {
  TrainingInput input;
  input.kind = static_cast<TrainingInput::Kind>(kind_->currentData().toInt());
  input.port = port_->value();
  input.script = script_->text().trimmed();
  return input;
}

void TrainingDialog::set_input(const TrainingInput& input) {
  kind_->setCurrentIndex(kind_->findData(static_cast<int>(input.kind)));
  port_->setValue(input.port);
  script_->setText(input.script);
}

double TrainingDialog::duration() const {
  return duration_->value();
}

void TrainingDialog::set_duration(double seconds) {
  duration_->setValue(seconds);
}

}  // namespace viscera::studio
