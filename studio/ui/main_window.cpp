#include "studio/ui/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDockWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>

#include "core/error.h"
#include "core/image/downsample.h"
#include "core/materials/shipped_materials.h"
#include "importers/volume/volume_reader.h"
#include "simulator/dynamics/hydrometra_sweep.h"
#include "studio/document/document_commands.h"
#include "studio/document/view_state.h"
#include "studio/ui/background_task.h"
#include "studio/ui/display_panel.h"
#include "studio/ui/material_panel.h"
#include "studio/ui/organ_panels.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/segmentation_panel.h"
#include "studio/ui/slice_views.h"
#include "studio/ui/volume_rendering.h"
#include "templates/template_catalog.h"

namespace viscera::studio {

MainWindow::MainWindow(MainWindowOptions options, QWidget* parent)
    : QMainWindow(parent), options_(std::move(options)) {
  launcher_.set_simulator(options_.simulator);
  autosave_ = new Autosave(document_, options_.recovery_dir, options_.autosave_interval_ms, this);
  connect(autosave_, &Autosave::autosave_failed, this, [this](const QString& message) {
    statusBar()->showMessage(tr("Autosave failed: %1").arg(message), 10'000);
  });
  connect(autosave_, &Autosave::autosaved, this,
          [this] { statusBar()->showMessage(tr("Autosaved a recovery copy"), 5'000); });

  view_ = new SceneView(this);
  setCentralWidget(view_);
  build_docks();
  build_menus();

  connect(&document_, &ScenarioDocument::changed, this, &MainWindow::on_document_changed);
  connect(&document_, &ScenarioDocument::status_changed, this, &MainWindow::update_title);
  connect(view_, &SceneView::object_picked, this, &MainWindow::select_object);
  connect(tree_, &SceneTree::object_selected, this, &MainWindow::select_object);
  connect(tree_, &SceneTree::visibility_changed, this,
          [this](const QStringList& keys, bool visible) { set_visible(keys, visible); });
  connect(materials_, &MaterialPanel::edit_failed, this, &MainWindow::show_error);
  connect(&launcher_, &TrainingLauncher::finished, this, &MainWindow::show_training_result);

  restore_layout();
  on_document_changed(ChangeKind::Everything, {});
  update_title();
}

MainWindow::~MainWindow() {
  autosave_->wait();
}

void MainWindow::build_docks() {
  tree_ = new SceneTree(this);
  auto* tree_dock = new QDockWidget(tr("Scene"), this);
  tree_dock->setObjectName("scene-dock");
  tree_dock->setWidget(tree_);
  addDockWidget(Qt::LeftDockWidgetArea, tree_dock);

  materials_ = new MaterialPanel(document_, this);
  auto* material_dock = new QDockWidget(tr("Material"), this);
  material_dock->setObjectName("material-dock");
  material_dock->setWidget(materials_);
  addDockWidget(Qt::RightDockWidgetArea, material_dock);

  report_ = new QPlainTextEdit(this);
  report_->setReadOnly(true);
  report_->setPlaceholderText(tr("Launch a training session to see its report here."));
  auto* report_dock = new QDockWidget(tr("Training report"), this);
  report_dock->setObjectName("report-dock");
  report_dock->setWidget(report_);
  addDockWidget(Qt::RightDockWidgetArea, report_dock);

  slices_ = new SliceViews(this);
  slice_dock_ = new QDockWidget(tr("Image volume"), this);
  slice_dock_->setObjectName("image-dock");
  slice_dock_->setWidget(slices_);
  addDockWidget(Qt::BottomDockWidgetArea, slice_dock_);
  slice_dock_->hide();
  connect(slices_, &SliceViews::changed, view_, &SceneView::render);

  segmentation_ = new SegmentationPanel(document_, this);
  auto* segmentation_dock = new QDockWidget(tr("Segmentation"), this);
  segmentation_dock->setObjectName("segmentation-dock");
  auto* segmentation_scroll = new QScrollArea(segmentation_dock);
  segmentation_scroll->setWidget(segmentation_);
  segmentation_scroll->setWidgetResizable(true);
  segmentation_dock->setWidget(segmentation_scroll);
  addDockWidget(Qt::RightDockWidgetArea, segmentation_dock);
  tabifyDockWidget(material_dock, segmentation_dock);
  material_dock->raise();
  segmentation_->set_error_handler([this](const QString& message) { show_error(message); });
  connect(segmentation_, &SegmentationPanel::organ_added, this, &MainWindow::select_object);
  connect(slices_, &SliceViews::point_clicked, segmentation_,
          [this](int, const core::Vec3& point) { segmentation_->set_seed(point); });
  build_volume_views();
  organ_panels_ = new OrganPanels(document_, *view_, *this);
  connect(organ_panels_, &OrganPanels::failed, this, &MainWindow::show_error);
  connect(organ_panels_, &OrganPanels::select_requested, this, &MainWindow::select_object);

  build_view_docks();
  build_asset_docks();
}

void MainWindow::update_title() {
  setWindowTitle(tr("%1[*] — Viscera Studio").arg(document_.display_name()));
  setWindowModified(document_.is_dirty());
}

void MainWindow::on_document_changed(ChangeKind kind, const QString& /*id*/) {
  if (kind == ChangeKind::Materials) return;  // the panel follows by itself
  // One view state for the tree, the 3D view and the package (issue 23 §4).
  const ViewState state = read_view_state().value_or(ViewState{});
  if (kind == ChangeKind::View) {
    view_->apply_view_state(state);
    tree_->apply_view_state(state);
    display_->refresh();
    return;
  }
  view_->show_scenario(document_.scenario(), document_.files(), kind == ChangeKind::Everything);
  tree_->show_scenario(document_.scenario(), state);
  select_object(view_->selected_object());
}

void MainWindow::select_object(const QString& id) {
  view_->select_object(id);
  tree_->select_object(view_->selected_object());
  materials_->show_object(view_->selected_object());
  organ_panels_->show_object(view_->selected_object());
  display_->show_object(view_->selected_object());
}

void MainWindow::show_error(const QString& message) {
  if (error_handler_) {
    error_handler_(message);
  } else {
    QMessageBox::critical(this, tr("Viscera Studio"), message);
  }
}

bool MainWindow::run(const QString& title, const std::function<void(core::Progress&)>& work) {
  const std::exception_ptr error = run_in_background(this, title, work);
  if (!error) return true;
  try {
    std::rethrow_exception(error);
  } catch (const core::CancelledError&) {
    statusBar()->showMessage(tr("%1: cancelled").arg(title), 5'000);
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
  }
  return false;
}

bool MainWindow::open_package(const std::filesystem::path& path) {
  DocumentContent content;
  if (!run(tr("Opening %1").arg(QString::fromStdString(path.filename().string())),
           [&](core::Progress& progress) { content = read_document_content(path, progress); })) {
    return false;
  }
  document_.adopt_opened(std::move(content), path);
  remember_recent(path);
  return true;
}

bool MainWindow::save() {
  if (document_.path().empty()) return ask_save_as();
  return save_as(document_.path());
}

bool MainWindow::save_as(const std::filesystem::path& path) {
  const DocumentContent snapshot = document_.content();
  if (!run(tr("Saving %1").arg(QString::fromStdString(path.filename().string())),
           [&](core::Progress& progress) { write_document_content(snapshot, path, progress); })) {
    return false;
  }
  document_.mark_saved(path);
  remember_recent(path);
  statusBar()->showMessage(tr("Saved %1").arg(QString::fromStdString(path.string())), 5'000);
  return true;
}

bool MainWindow::new_from_template(const std::string& name,
                                   const std::map<std::string, std::string>& overrides,
                                   std::uint64_t seed) {
  core::Scenario scenario;
  if (!run(tr("Building %1").arg(QString::fromStdString(name)), [&](core::Progress& progress) {
        scenario = templates::build_from_template(name, overrides, seed, progress);
        // The same pipeline step as `viscera new`: the hydrometra's pressure states.
        sim::add_hydrometra_states(scenario, progress);
      })) {
    return false;
  }
  document_.reset({std::move(scenario), {}});
  return true;
}

bool MainWindow::open_image_volume(const std::filesystem::path& path) {
  core::ImageVolume volume;
  if (!run(tr("Reading %1").arg(QString::fromStdString(path.filename().string())),
           [&](core::Progress& progress) {
             progress.begin_stage("reading the image volume", 1);
             volume = importers::read_volume(path).volume;
             progress.step();
           })) {
    return false;
  }
  show_image_volume(volume);
  return true;
}

bool MainWindow::downsample_image_volume(const std::array<int, 3>& factors) {
  core::ImageVolume coarse;
  const core::ImageVolume& volume = segmentation_->segmentation().volume();
  if (!run(tr("Downsampling the image volume"), [&](core::Progress& progress) {
        progress.begin_stage("downsampling the image volume", 1);
        if (volume.voxel_count() == 0) throw core::UsageError("open an image volume first");
        coarse = core::downsample(volume, factors);
        progress.step();
      })) {
    return false;
  }
  show_image_volume(coarse);
  return true;
}

void MainWindow::show_image_volume(const core::ImageVolume& volume) {
  slices_->set_volume(volume);
  segmentation_->set_volume(volume);
  volume_rendering_->set_volume(volume);
  // The transfer function the data asks for (a label image coloured by label, not as CT).
  const QString preset = QString::fromStdString(volume_rendering_->preset_for_data());
  volume_rendering_->apply_preset(preset.toStdString());
  for (QAction* action : preset_actions_->actions())
    action->setChecked(action->text() == preset);
  slice_dock_->show();
  view_->set_image_planes(
      {slices_->plane_in_3d(0), slices_->plane_in_3d(1), slices_->plane_in_3d(2)});
  set_slice_planes_shown(true);
  view_->reset_camera();
  view_->render();
}

bool MainWindow::create_primitive(const PrimitiveRequest& request) {
  // The new object takes the selected object's material, else the scenario's first, else
  // myometrium from the shipped library.
  const auto& scenario = document_.scenario();
  core::Material material;
  const core::SceneObject* selected = scenario.find_object(view_->selected_object().toStdString());
  if (selected != nullptr && scenario.materials.contains(selected->material)) {
    material = scenario.materials.at(selected->material);
  } else if (!scenario.materials.empty()) {
    material = scenario.materials.begin()->second;
  } else {
    material = core::shipped_material("myometrium");
  }
  const std::string id = unique_object_id(scenario, to_string(request.kind));
  core::SceneObject object;
  if (!run(tr("Creating %1").arg(QString::fromStdString(id)), [&](core::Progress& progress) {
        object = build_primitive_object(request, id, material, progress);
      })) {
    return false;
  }
  try {
    document_.undo_stack()->push(new AddObjectCommand(document_, std::move(object), material));
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return false;
  }
  select_object(QString::fromStdString(id));
  return true;
}

bool MainWindow::export_session_package() {
  try {
    const std::filesystem::path package = launcher_.prepare().toStdString();
    const DocumentContent snapshot = document_.content();
    return run(tr("Exporting the session package"), [&](core::Progress& progress) {
      write_document_content(snapshot, package, progress);
    });
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return false;
  }
}

bool MainWindow::launch_training(double duration_s, const QString& script) {
  if (!export_session_package()) return false;
  try {
    launcher_.start(duration_s, script);
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return false;
  }
  report_->setPlainText(tr("Training session running…"));
  statusBar()->showMessage(tr("Training session running"));
  return true;
}

bool MainWindow::launch_interactive_training(const TrainingInput& input, double duration_s) {
  if (!export_session_package()) return false;
  try {
    launcher_.start_interactive(input, duration_s);
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return false;
  }
  report_->setPlainText(tr("Training session running in the endoscopic view…"));
  statusBar()->showMessage(tr("Training session running in the endoscopic view"));
  return true;
}

void MainWindow::show_training_result(const TrainingResult& result) {
  QString text = summarize_report(result.report);
  const QString failure = failure_sentence(result);
  if (result.report.is_null() && !failure.isEmpty()) text = failure;
  report_->setPlainText(text);
  if (auto* dock = findChild<QDockWidget*>(QStringLiteral("report-dock"))) {
    dock->show();
    dock->raise();
  }
  statusBar()->showMessage(tr("Training session ended"), 5'000);
  if (!failure.isEmpty()) show_error(failure);
  emit training_finished(result);
}

QString MainWindow::report_text() const {
  return report_->toPlainText();
}

bool MainWindow::offer_recovery(std::function<bool(const RecoveryCopy&)> ask) {
  const auto copy = Autosave::find_recovery(options_.recovery_dir);
  if (!copy) return false;
  if (!ask) {
    ask = [this](const RecoveryCopy& c) {
      const QString of = c.original_path.empty() ? tr("an untitled document")
                                                 : QString::fromStdString(c.original_path.string());
      return QMessageBox::question(
                 this, tr("Recover unsaved work"),
                 tr("Viscera Studio did not close normally. Recover the unsaved changes to %1 "
                    "autosaved at %2?")
                     .arg(of, c.written.toLocalTime().toString(Qt::TextDate))) == QMessageBox::Yes;
    };
  }
  if (!ask(*copy)) {
    autosave_->discard();
    return false;
  }
  DocumentContent content;
  if (!run(tr("Recovering"), [&](core::Progress& progress) {
        content = read_document_content(copy->package, progress);
      })) {
    return false;
  }
  document_.reset(std::move(content), copy->original_path, true);
  return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybe_save()) {
    event->ignore();
    return;
  }
  launcher_.stop();
  autosave_->wait();
  autosave_->discard();
  save_layout();
  event->accept();
}

bool MainWindow::maybe_save() {
  if (!document_.is_dirty()) return true;
  const auto answer = QMessageBox::question(
      this, tr("Viscera Studio"), tr("Save the changes to %1?").arg(document_.display_name()),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Cancel) return false;
  return answer == QMessageBox::Discard || save();
}

QStringList MainWindow::recent_files() const {
  return QSettings().value(QStringLiteral("recent_files")).toStringList();
}

void MainWindow::remember_recent(const std::filesystem::path& path) {
  const QString file = QString::fromStdString(std::filesystem::absolute(path).string());
  QStringList files = recent_files();
  files.removeAll(file);
  files.prepend(file);
  while (files.size() > 8)
    files.removeLast();
  QSettings().setValue(QStringLiteral("recent_files"), files);
  rebuild_recent_menu();
}

}  // namespace viscera::studio
