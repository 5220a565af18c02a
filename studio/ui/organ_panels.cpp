#include "studio/ui/organ_panels.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>

#include "studio/ui/control_points.h"
#include "studio/ui/deformation_panel.h"
#include "studio/ui/material_fit_panel.h"
#include "studio/ui/pathology_panel.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/texture_panel.h"
#include "studio/ui/vessel_panel.h"

namespace viscera::studio {

OrganPanels::OrganPanels(ScenarioDocument& document, SceneView& view, QMainWindow& window)
    : QObject(&window) {
  texture_ = new TexturePanel(document, &window);
  vessels_ = new VesselPanel(document, &window);
  pathologies_ = new PathologyPanel(document, &window);
  material_fit_ = new MaterialFitPanel(document, &window);
  control_points_ = new ControlPointPanel(document, view, &window);
  deformation_ = new DeformationPanel(document, view, &window);
  // Tabbed with the material dock when there is one, so the 3D view keeps its width.
  QDockWidget* first = window.findChild<QDockWidget*>(QStringLiteral("material-dock"));
  QDockWidget* raised = first;
  const std::pair<OrganPanel*, QString> panels[] = {{texture_, tr("Texture")},
                                                    {vessels_, tr("Vessels")},
                                                    {pathologies_, tr("Pathologies")},
                                                    {deformation_, tr("Motion")},
                                                    {material_fit_, tr("Stress–strain")},
                                                    {control_points_, tr("Control points")}};
  for (const auto& [panel, title] : panels) {
    auto* dock = new QDockWidget(title, &window);
    dock->setObjectName(QString(panel->metaObject()->className()).section("::", -1) + "-dock");
    // In a scroll area, so the tallest or widest panel does not squeeze the 3D view.
    auto* scroll = new QScrollArea(dock);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(panel);
    dock->setWidget(scroll);
    window.addDockWidget(Qt::RightDockWidgetArea, dock);
    if (first != nullptr) {
      window.tabifyDockWidget(first, dock);
    } else {
      first = raised = dock;
    }
    connect(panel, &OrganPanel::failed, this, &OrganPanels::failed);
  }
  raised->raise();
  connect(&view, &SceneView::surface_clicked, pathologies_, &PathologyPanel::on_surface_clicked);
  connect(pathologies_, &PathologyPanel::placed, this, &OrganPanels::select_requested);
  connect(control_points_, &ControlPointPanel::created, this, &OrganPanels::select_requested);
}

void OrganPanels::show_object(const QString& id) {
  texture_->show_object(id);
  vessels_->show_object(id);
  pathologies_->show_object(id);
  material_fit_->show_object(id);
  control_points_->show_object(id);
  deformation_->show_object(id);
}

}  // namespace viscera::studio
