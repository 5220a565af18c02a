#pragma once
/// The stress–strain panel (issue 9 §5; seed 001 §3.2 "approximated by polynomials third
/// degree"): measured samples of the selected object's material, loaded from a CSV
/// (core::read_stress_strain_csv, as `viscera material fit`) and editable in a table, the
/// least-squares cubic σ(ε) = c1 ε + c2 ε|ε| + c3 ε³ (core::fit_cubic_stress) refitted on every
/// edit and plotted over the samples, and "Apply", which sets the material's curve and its
/// Teschner constants (core::material_from_measured_curve) as one undoable command.

#include <filesystem>
#include <optional>
#include <vector>

#include "core/materials/cubic_stress_fit.h"
#include "studio/ui/organ_panel.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace viscera::studio {

class StressStrainPlot;

class MaterialFitPanel : public OrganPanel {
  Q_OBJECT

 public:
  explicit MaterialFitPanel(ScenarioDocument& document, QWidget* parent = nullptr);

  /// Reads the samples of a stress–strain CSV into the table; false (after failed()) for a file
  /// the reader refuses.
  bool load_csv(const std::filesystem::path& path);
  /// Replaces the samples (strain, stress in Pa).
  void set_samples(const std::vector<double>& strain, const std::vector<double>& stress);
  /// Sets one sample as if typed into the table (row, column 0 strain / 1 stress in Pa).
  void edit_sample(int row, int column, double value);
  /// The samples in the table.
  core::StressStrainCurve samples() const;
  /// The current fit, or nothing while the samples cannot be fitted.
  const std::optional<core::CubicStressFit>& fit() const { return fit_; }
  /// Gives the shown object's material the fitted curve and constants; false (after failed())
  /// without an object, a scenario material or a usable fit.
  bool apply_fit();

  StressStrainPlot* plot() const { return plot_; }

 private:
  void refresh() override;
  void refit();

  QLabel* object_label_ = nullptr;
  QTableWidget* table_ = nullptr;
  StressStrainPlot* plot_ = nullptr;
  QLabel* fit_label_ = nullptr;
  QDoubleSpinBox* poisson_ = nullptr;
  QPushButton* apply_ = nullptr;
  std::optional<core::CubicStressFit> fit_;
  QString fit_error_;
  bool updating_ = false;
};

}  // namespace viscera::studio
