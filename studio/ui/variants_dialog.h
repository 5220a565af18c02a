#pragma once
/// The "Generate variants…" dialog (issue 9 §6): how many variants, the batch seed, the source
/// (the document's template when it has one, else the scenario itself; variant_batch.h), the
/// draws per variant and whether each variant also runs the simulated second.

#include <QDialog>

#include "core/scenario/scenario.h"
#include "studio/document/variant_batch.h"

class QCheckBox;
class QComboBox;
class QSpinBox;
class QLineEdit;

namespace viscera::studio {

class VariantsDialog : public QDialog {
  Q_OBJECT

 public:
  /// Offers the Template source only when `scenario` has one (has_template_source).
  explicit VariantsDialog(const core::Scenario& scenario, QWidget* parent = nullptr);

  /// The request as set in the dialog.
  VariantRequest request() const;

 private:
  QComboBox* source_ = nullptr;
  QSpinBox* count_ = nullptr;
  QLineEdit* seed_ = nullptr;
  QSpinBox* attempts_ = nullptr;
  QCheckBox* simulate_ = nullptr;
};

}  // namespace viscera::studio
