#pragma once
/// New from template (issue 9; DESIGN.md §9 `viscera new`): pick a catalogue template, set its
/// parameters within their documented ranges and units, and a seed. The studio then builds the
/// scenario with templates::build_from_template, as the CLI does.

#include <QDialog>
#include <cstdint>
#include <map>
#include <string>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QSpinBox;

namespace viscera::studio {

class TemplateDialog : public QDialog {
  Q_OBJECT

 public:
  explicit TemplateDialog(QWidget* parent = nullptr);

  /// Selects template `name`; false if the catalogue has none of that name.
  bool select_template(const std::string& name);
  std::string template_name() const;
  /// Sets a parameter editor; false for an unknown parameter.
  bool set_parameter(const std::string& name, double value);
  /// Parameters that differ from the template's defaults, as `viscera new --set` text values.
  std::map<std::string, std::string> overrides() const;
  std::uint64_t seed() const;
  void set_seed(std::uint64_t seed);

 private:
  void show_parameters();

  QComboBox* templates_ = nullptr;
  QLabel* description_ = nullptr;
  QFormLayout* form_ = nullptr;
  QSpinBox* seed_ = nullptr;
  std::map<std::string, QDoubleSpinBox*> editors_;
  std::map<std::string, double> defaults_;
};

}  // namespace viscera::studio
