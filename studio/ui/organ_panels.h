#pragma once
/// The organ panels of the main window (issue 9 §5) and their docks: texture, vessels,
/// pathologies, active deformation, the stress–strain fit and model control points, tabbed on the
/// right. They follow the selection; the pathology panel listens to clicks on surfaces in the 3D
/// view. The main window constructs this once and forwards the selection; tests reach every panel's
/// public actions through it.

#include <QObject>

#include "studio/document/scenario_document.h"

class QMainWindow;

namespace viscera::studio {

class ControlPointPanel;
class DeformationPanel;
class MaterialFitPanel;
class PathologyPanel;
class SceneView;
class TexturePanel;
class VesselPanel;

class OrganPanels : public QObject {
  Q_OBJECT

 public:
  /// Builds the panels and docks them into `window`.
  OrganPanels(ScenarioDocument& document, SceneView& view, QMainWindow& window);

  /// The selected object (empty: none).
  void show_object(const QString& id);

  TexturePanel* texture() const { return texture_; }
  VesselPanel* vessels() const { return vessels_; }
  PathologyPanel* pathologies() const { return pathologies_; }
  MaterialFitPanel* material_fit() const { return material_fit_; }
  ControlPointPanel* control_points() const { return control_points_; }
  DeformationPanel* deformation() const { return deformation_; }

 signals:
  /// A panel's action failed (one sentence).
  void failed(const QString& message);
  /// A panel created this object and wants it selected.
  void select_requested(const QString& id);

 private:
  TexturePanel* texture_ = nullptr;
  VesselPanel* vessels_ = nullptr;
  PathologyPanel* pathologies_ = nullptr;
  MaterialFitPanel* material_fit_ = nullptr;
  ControlPointPanel* control_points_ = nullptr;
  DeformationPanel* deformation_ = nullptr;
};

}  // namespace viscera::studio
