// The main window's seeing-inside and visibility model (issue 23 §2, §4), File ▸ Close, closing
// the image volume, and the remembered window layout (issue 23 §6).

#include <QAction>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMenu>
#include <QScreen>
#include <QSettings>
#include <QShowEvent>
#include <QUndoStack>
#include <algorithm>

#include "core/error.h"
#include "studio/document/view_state.h"
#include "studio/ui/display_panel.h"
#include "studio/ui/main_window.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/segmentation_panel.h"
#include "studio/ui/slice_views.h"
#include "studio/ui/volume_rendering.h"

namespace viscera::studio {
namespace {

const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
/// Bump when the docks change so an old saved layout is not applied to new docks.
constexpr int kLayoutVersion = 23;

}  // namespace

void MainWindow::build_view_docks() {
  display_ = new DisplayPanel(document_, *view_, this);
  auto* dock = new QDockWidget(tr("Display"), this);
  dock->setObjectName("display-dock");
  dock->setWidget(display_);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  connect(display_, &DisplayPanel::opacity_requested, this,
          [this](const QString& id, double opacity) { set_object_opacity(id, opacity); });
  connect(display_, &DisplayPanel::failed, this, &MainWindow::show_error);
  // With the slices: the clipping plane goes through the slice of its orientation.
  const auto follow = [this] {
    if (!has_image_volume()) return;
    const core::ImageVolume& volume = segmentation_->segmentation().volume();
    const int axis = display_->clip_axis();
    core::Vec3 ijk(0.5 * (volume.dims[0] - 1), 0.5 * (volume.dims[1] - 1),
                   0.5 * (volume.dims[2] - 1));
    ijk[axis] = slices_->slice(axis);
    display_->follow_slice(volume.index_to_world(ijk));
  };
  connect(display_, &DisplayPanel::slice_plane_requested, this, follow);
  connect(slices_, &SliceViews::changed, this, follow);
}

void MainWindow::build_view_menu_items(QMenu* file, QMenu* view) {
  file->addAction(tr("&Close"), this, [this] { close_document(); })
      ->setShortcut(QKeySequence::Close);
  file->addAction(tr("Close image &volume"), this, [this] { close_image_volume(); });
  view->addAction(tr("From the &cervix into the cavity"), this,
                  [this] { display_->view_from_cervix(); });
  slice_planes_action_ = view->addAction(tr("&Slice planes in 3D"));
  slice_planes_action_->setCheckable(true);
  slice_planes_action_->setEnabled(false);
  connect(slice_planes_action_, &QAction::toggled, this,
          [this](bool on) { set_slice_planes_shown(on); });
}

std::optional<ViewState> MainWindow::read_view_state() {
  try {
    return view_state_of(document_.files());
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return std::nullopt;
  }
}

bool MainWindow::set_visible(const QStringList& keys, bool visible) {
  const std::optional<ViewState> current = read_view_state();
  if (!current) return false;
  ViewState state = *current;
  const ViewState before = state;
  for (const QString& key : keys) {
    if (key == SceneTree::kImageVolumeKey) {
      set_slice_planes_shown(visible);
      continue;
    }
    if (visible) {
      state.hidden.erase(key.toStdString());
    } else {
      state.hidden.insert(key.toStdString());
    }
  }
  if (state == before) return true;
  const QString what = keys.size() == 1 ? keys.front() : tr("%1 items").arg(keys.size());
  document_.undo_stack()->push(new SetViewStateCommand(
      document_, std::move(state), visible ? tr("Show %1").arg(what) : tr("Hide %1").arg(what)));
  return true;
}

bool MainWindow::set_object_opacity(const QString& id, double opacity) {
  if (document_.scenario().find_object(id.toStdString()) == nullptr) {
    show_error(tr("There is no object \"%1\" to change the opacity of.").arg(id));
    return false;
  }
  const std::optional<ViewState> current = read_view_state();
  if (!current) return false;
  ViewState state = *current;
  const double value = std::clamp(opacity, 0.05, 1.0);
  if (value >= 1.0) {
    state.opacity.erase(id.toStdString());
  } else {
    state.opacity[id.toStdString()] = value;
  }
  document_.undo_stack()->push(new SetViewStateCommand(
      document_, std::move(state), tr("Opacity of %1").arg(id), "opacity/" + id.toStdString()));
  return true;
}

bool MainWindow::close_document() {
  if (!maybe_save()) return false;
  close_image_volume();
  document_.reset({}, {}, false);
  return true;
}

bool MainWindow::has_image_volume() const {
  return volume_rendering_->has_volume();
}

void MainWindow::close_image_volume() {
  view_->set_image_planes({});
  set_volume_rendering(false);
  volume_rendering_->clear();
  segmentation_->set_volume(core::ImageVolume{});
  slice_dock_->hide();
  slice_planes_action_->setEnabled(false);
  tree_->show_image_volume(false, false);
  view_->render();
}

void MainWindow::set_slice_planes_shown(bool shown) {
  const bool present = has_image_volume();
  for (int axis = 0; axis < 3; ++axis)
    slices_->plane_in_3d(axis)->SetVisibility(shown && present);
  slice_planes_action_->setEnabled(present);
  if (slice_planes_action_->isChecked() != (shown && present)) {
    const bool blocked = slice_planes_action_->blockSignals(true);
    slice_planes_action_->setChecked(shown && present);
    slice_planes_action_->blockSignals(blocked);
  }
  tree_->show_image_volume(present, shown && present);
  view_->render();
}

bool MainWindow::slice_planes_shown() const {
  return has_image_volume() && slices_->plane_in_3d(0)->GetVisibility() != 0;
}

void MainWindow::restore_layout() {
  // Tabs of the right-hand docks run down the window's edge with their full titles.
  setTabPosition(Qt::RightDockWidgetArea, QTabWidget::East);
  setDockOptions(dockOptions() | QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
  const QSettings settings;
  const QByteArray geometry = settings.value(kGeometryKey).toByteArray();
  const QByteArray state = settings.value(kStateKey).toByteArray();
  if (!geometry.isEmpty() && restoreGeometry(geometry) && !state.isEmpty() &&
      restoreState(state, kLayoutVersion)) {
    restored_state_ = state;
    return;
  }
  // First run: most of the screen, narrow docks, the 3D view the largest pane.
  const QScreen* screen = QGuiApplication::primaryScreen();
  const QRect available = screen != nullptr ? screen->availableGeometry() : QRect(0, 0, 1280, 800);
  resize(std::max(1024, available.width() * 9 / 10), std::max(700, available.height() * 9 / 10));
  QList<QDockWidget*> left, right;
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    if (dockWidgetArea(dock) == Qt::LeftDockWidgetArea && !tabifiedDockWidgets(dock).isEmpty())
      continue;
    if (dockWidgetArea(dock) == Qt::LeftDockWidgetArea) left << dock;
    if (dockWidgetArea(dock) == Qt::RightDockWidgetArea) right << dock;
  }
  // The dock widths apply once the window is laid out (showEvent).
  first_layout_docks_ = {left.isEmpty() ? nullptr : left.front(),
                         right.isEmpty() ? nullptr : right.front()};
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (!restored_state_.isEmpty()) {
    restoreState(restored_state_, kLayoutVersion);
    restored_state_.clear();
  }
  const int side = std::clamp(width() / 6, 220, 320);
  if (first_layout_docks_[0] != nullptr)
    resizeDocks({first_layout_docks_[0]}, {side}, Qt::Horizontal);
  if (first_layout_docks_[1] != nullptr)
    resizeDocks({first_layout_docks_[1]}, {side + 60}, Qt::Horizontal);
  first_layout_docks_ = {nullptr, nullptr};
}

void MainWindow::save_layout() const {
  QSettings settings;
  settings.setValue(kGeometryKey, saveGeometry());
  settings.setValue(kStateKey, saveState(kLayoutVersion));
}

}  // namespace viscera::studio
