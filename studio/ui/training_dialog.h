#pragma once
/// Training ▸ Launch (issue 16 item 5): what drives the instrument of an interactive session —
/// keyboard and mouse, a gamepad, a haptic device over UDP on a port, or a script — and how long
/// it may last. The studio then opens the simulator's endoscopic view on the document's patient
/// (TrainingLauncher::start_interactive) and shows the report when the session ends.

#include <QDialog>

#include "studio/ui/training_launcher.h"

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace viscera::studio {

class TrainingDialog : public QDialog {
  Q_OBJECT

 public:
  explicit TrainingDialog(QWidget* parent = nullptr);

  /// The input chosen.
  TrainingInput input() const;
  void set_input(const TrainingInput& input);
  /// Session length in s; 0: the scenario's own limit.
  double duration() const;
  void set_duration(double seconds);

 private:
  void show_input_fields();

  QComboBox* kind_ = nullptr;
  QSpinBox* port_ = nullptr;
  QLineEdit* script_ = nullptr;
  QWidget* script_row_ = nullptr;
  QDoubleSpinBox* duration_ = nullptr;
};

}  // namespace viscera::studio
