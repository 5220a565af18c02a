#pragma once
/// The active deformation panel (issue 9 §5; seed 001 §5): organ motility of the selected object
/// (amplitude mean and variance, wave speed and direction, frequency and its disturbance,
/// impulsive contraction timing) and the pulse on one of its vessel trees (heart rate, pulse
/// velocity, wall force), each applied as one undoable command after the checks of
/// textures/active_deformation_specs.h. "Preview" animates the object's surface in the 3D view
/// with a QTimer by sim::OrganMotility — the displacement function of the simulator's physics —
/// and stops, restoring the surface, when switched off, when the selection changes or when the
/// panel is hidden.

#include <QElapsedTimer>

#include "core/scenario/scenario_parts.h"
#include "studio/ui/organ_panel.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTimer;

namespace viscera::studio {

class SceneView;

class DeformationPanel : public OrganPanel {
  Q_OBJECT

 public:
  DeformationPanel(ScenarioDocument& document, SceneView& view, QWidget* parent = nullptr);
  ~DeformationPanel() override;

  void show_object(const QString& id) override;
  /// The motility the editors show, and setting them.
  core::MotilitySpec motility() const;
  void set_motility(const core::MotilitySpec& spec);
  /// Adds or replaces "<object>-motility" with the editors' spec; false after failed().
  bool apply_motility();
  /// Adds or replaces "<tree>-pulse" on vessel tree `tree` of the shown object.
  bool apply_pulse(const QString& tree, double heart_rate_bpm, double pulse_velocity,
                   double wall_force);

  /// Starts / stops the animated preview (stopping puts the surface back at rest).
  bool start_preview();
  void stop_preview();
  bool previewing() const;
  /// Shows the preview's surface at time `t` s (what each timer tick does with the elapsed time).
  void preview_at(double t);

  /// Seed of the drawn amplitudes and frequencies in the preview.
  static constexpr std::uint64_t kPreviewSeed = 1;

 protected:
  void hideEvent(QHideEvent* event) override;

 private:
  void refresh() override;

  SceneView& view_;
  QLabel* label_ = nullptr;
  QDoubleSpinBox* amplitude_mm_ = nullptr;
  QDoubleSpinBox* amplitude_variance_mm2_ = nullptr;
  QDoubleSpinBox* wave_speed_mm_s_ = nullptr;
  QDoubleSpinBox* direction_[3] = {nullptr, nullptr, nullptr};
  QDoubleSpinBox* frequency_ = nullptr;
  QDoubleSpinBox* frequency_disturbance_ = nullptr;
  QDoubleSpinBox* interval_mean_ = nullptr;
  QDoubleSpinBox* interval_variance_ = nullptr;
  QComboBox* tree_ = nullptr;
  QDoubleSpinBox* heart_rate_ = nullptr;
  QDoubleSpinBox* pulse_velocity_ = nullptr;
  QDoubleSpinBox* wall_force_ = nullptr;
  QPushButton* preview_button_ = nullptr;
  QTimer* timer_ = nullptr;
  QElapsedTimer clock_;
  QString previewed_;  ///< object whose actor the preview moves
};

}  // namespace viscera::studio
