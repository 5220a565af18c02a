#pragma once
/// The vessel panel (issue 9 §5; seed 000 §1.2, seed 001 §5.1.1): grows a vessel tree in the
/// selected organ by CCO (terminal segments, Murray exponent) or the built-in L-system
/// (generations, root radius), with a seed, off the UI thread with progress, exactly as
/// `viscera vessels --domain PACKAGE --object ID` does, and adds it as one undoable command.

#include "studio/document/organ_authoring.h"
#include "studio/ui/organ_panel.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace viscera::studio {

class VesselPanel : public OrganPanel {
  Q_OBJECT

 public:
  explicit VesselPanel(ScenarioDocument& document, QWidget* parent = nullptr);

  /// Grows `request` in the shown object and adds the tree; false (after failed()) without an
  /// object, when the organ leaves no room, or when cancelled.
  bool generate_vessels(const VesselRequest& request);
  /// Grows what the editors show.
  bool generate();
  VesselRequest request() const;
  void set_request(const VesselRequest& request);

 private:
  void refresh() override;
  void update_enabled();

  QLabel* object_label_ = nullptr;
  QComboBox* method_ = nullptr;
  QSpinBox* terminals_ = nullptr;
  QSpinBox* generations_ = nullptr;
  QDoubleSpinBox* root_radius_mm_ = nullptr;
  QDoubleSpinBox* murray_ = nullptr;
  QSpinBox* seed_ = nullptr;
  QPushButton* generate_ = nullptr;
};

}  // namespace viscera::studio
