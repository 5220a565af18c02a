// The main window's volume rendering and label overlay: construction, the View menu's
// volume-rendering entries and the public functions behind them.

#include <QAction>
#include <QActionGroup>
#include <QMenu>

#include "studio/ui/label_overlay.h"
#include "studio/ui/main_window.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/segmentation_panel.h"
#include "studio/ui/volume_rendering.h"

namespace viscera::studio {

void MainWindow::build_volume_views() {
  volume_rendering_ = std::make_unique<VolumeRendering>();
  volume_rendering_->prop()->SetVisibility(false);
  view_->renderer()->AddViewProp(volume_rendering_->prop());
  overlay_ = new LabelOverlay(slices_, view_, this);
  connect(segmentation_, &SegmentationPanel::labels_changed, overlay_,
          [this] { overlay_->set_labels(segmentation_->segmentation().labels()); });
}

void MainWindow::build_volume_menu(QMenu* view) {
  view->addSeparator();
  volume_action_ = view->addAction(tr("&Volume rendering"));
  volume_action_->setCheckable(true);
  connect(volume_action_, &QAction::toggled, this, [this](bool on) { set_volume_rendering(on); });
  QMenu* presets = view->addMenu(tr("Volume &preset"));
  preset_actions_ = new QActionGroup(this);
  for (const auto& preset : volume_presets()) {
    const QString name = QString::fromStdString(preset.name);
    QAction* action = presets->addAction(name, this, [this, name] { set_volume_preset(name); });
    action->setCheckable(true);
    action->setChecked(preset.name == volume_rendering_->preset());
    preset_actions_->addAction(action);
  }
  QAction* overlay_3d = view->addAction(tr("&Labels in 3D"));
  overlay_3d->setCheckable(true);
  connect(overlay_3d, &QAction::toggled, overlay_, &LabelOverlay::set_shown_in_3d);
}

void MainWindow::set_volume_rendering(bool shown) {
  volume_rendering_->prop()->SetVisibility(shown && volume_rendering_->has_volume());
  if (volume_action_->isChecked() != shown) volume_action_->setChecked(shown);
  view_->render();
}

bool MainWindow::volume_rendering_shown() const {
  return volume_rendering_->prop()->GetVisibility() != 0;
}

bool MainWindow::set_volume_preset(const QString& name) {
  if (!volume_rendering_->has_volume()) {
    show_error(tr("Open an image volume before rendering it."));
    return false;
  }
  if (!volume_rendering_->apply_preset(name.toStdString())) {
    show_error(tr("There is no volume rendering preset \"%1\".").arg(name));
    return false;
  }
  for (QAction* action : preset_actions_->actions())
    action->setChecked(action->text() == name);
  set_volume_rendering(true);
  return true;
}

}  // namespace viscera::studio
