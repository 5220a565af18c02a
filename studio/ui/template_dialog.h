#pragma once
/// New from template (issues 9 and 23; DESIGN.md §9 `viscera new`): pick a catalogue template,
/// set its parameters and a seed. The form is generated from the template's parameter
/// descriptions (templates::TemplateParameter): one field per parameter in clinical units (mm,
/// degrees, ml, kPa; clinical_units.h) with its range, a readable label and its one-line
/// description, grouped by templates::parameter_group (anatomy, pathologies, tissue, vessels,
/// texture, meshing) inside a scroll area, so the dialog fits a 768-px-high screen whatever the
/// template. The studio then builds the scenario with templates::build_from_template, as the
/// CLI does; values go back in SI.

#include <QDialog>
#include <cstdint>
#include <map>
#include <string>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QScrollArea;
class QSpinBox;
class QVBoxLayout;

namespace viscera::studio {

class TemplateDialog : public QDialog {
  Q_OBJECT

 public:
  explicit TemplateDialog(QWidget* parent = nullptr);

  /// Selects template `name`; false if the catalogue has none of that name.
  bool select_template(const std::string& name);
  std::string template_name() const;
  /// Sets a parameter editor to `value` in the parameter's SI unit; false for an unknown
  /// parameter.
  bool set_parameter(const std::string& name, double value);
  /// The editor of parameter `name` (shown in clinical units), or null.
  QDoubleSpinBox* editor(const std::string& name) const;
  /// Parameters whose editors differ from the template's defaults, as `viscera new --set` text
  /// values in SI units.
  std::map<std::string, std::string> overrides() const;
  std::uint64_t seed() const;
  void set_seed(std::uint64_t seed);
  /// Sizes the dialog to fit inside `available` (a screen's available geometry, window frame
  /// included); the parameters scroll when they do not fit. Called on show with the dialog's
  /// screen.
  void fit_to(const QRect& available);
  QDialogButtonBox* buttons() const { return buttons_; }
  QScrollArea* parameter_area() const { return scroll_; }

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  void show_parameters();

  /// One parameter's editor and the factor between its shown value and SI.
  struct Field {
    QDoubleSpinBox* editor = nullptr;
    double scale = 1.0;
    double shown_default = 0.0;           ///< the default as the editor shows it (rounded)
    double minimum = 0.0, maximum = 0.0;  ///< SI range
    bool integer = false;
  };

  QComboBox* templates_ = nullptr;
  QLabel* description_ = nullptr;
  QScrollArea* scroll_ = nullptr;
  QSpinBox* seed_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
  std::map<std::string, Field> fields_;
};

}  // namespace viscera::studio
