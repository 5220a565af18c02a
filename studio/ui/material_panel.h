#pragma once
/// The material property panel (issue 9 §5; seed 001 §3.3 "material user interface"): for the
/// selected object, a picker over the scenario's materials and the shipped tissue library
/// (core::shipped_materials, data/materials/tissues.json), and editors for the material's
/// parameters. Every change is pushed as an undoable command on the document.

#include <QWidget>
#include <map>

#include "studio/document/document_commands.h"
#include "studio/document/scenario_document.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace viscera::studio {

class MaterialPanel : public QWidget {
  Q_OBJECT

 public:
  MaterialPanel(ScenarioDocument& document, QWidget* parent = nullptr);

  /// Shows the material of object `id` (empty: nothing selected; the panel then says "Select an
  /// object" and shows no material and no numbers).
  void show_object(const QString& id);
  /// Picks entry `material_id` (scenario material or shipped tissue) as if the user chose it.
  /// Returns false when no object is shown or the id is unknown.
  bool choose_material(const QString& material_id);
  /// Sets a field as if typed into its spin box.
  bool edit_field(MaterialField field, double value);

  QComboBox* picker() const { return picker_; }
  /// The picker and the parameter editors (hidden with nothing selected).
  QWidget* editors_box() const { return editors_box_; }
  QDoubleSpinBox* field_editor(MaterialField field) const { return editors_.at(field); }

 signals:
  /// An edit was refused; the message is one sentence.
  void edit_failed(const QString& message);

 private:
  void refresh();
  void push(QUndoCommand* command);

  ScenarioDocument& document_;
  QString object_id_;
  bool updating_ = false;
  QLabel* object_label_ = nullptr;
  QWidget* editors_box_ = nullptr;
  QComboBox* picker_ = nullptr;
  QLabel* source_label_ = nullptr;
  std::map<MaterialField, QDoubleSpinBox*> editors_;
};

}  // namespace viscera::studio
