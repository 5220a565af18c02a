// The menus of the main window and the small dialogs behind them.

#include <QApplication>
#include <QFileDialog>
#include <QInputDialog>
#include <QMenuBar>
#include <QUndoStack>

#include "core/error.h"
#include "studio/document/document_commands.h"
#include "studio/ui/main_window.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/segmentation_panel.h"
#include "studio/ui/template_dialog.h"
#include "studio/ui/training_dialog.h"
#include "studio/ui/variants_dialog.h"
#include "templates/template_catalog.h"

namespace viscera::studio {

void MainWindow::build_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&New from template…"), this,
                  [this] {
                    if (!maybe_save()) return;
                    TemplateDialog dialog(this);
                    if (dialog.exec() == QDialog::Accepted) {
                      new_from_template(dialog.template_name(), dialog.overrides(), dialog.seed());
                    }
                  })
      ->setShortcut(QKeySequence::New);
  QAction* open = file->addAction(tr("&Open…"), this, [this] {
    if (!maybe_save()) return;
    const QString path = QFileDialog::getExistingDirectory(
        this, tr("Open a package folder (.vscene)"), QString(), QFileDialog::ShowDirsOnly);
    if (!path.isEmpty()) open_package(path.toStdString());
  });
  open->setShortcut(QKeySequence::Open);
  file->addAction(tr("Open &zipped package…"), this, [this] {
    if (!maybe_save()) return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a zipped package"), QString(),
                                                      tr("Packages (*.vscz)"));
    if (!path.isEmpty()) open_package(path.toStdString());
  });
  file->addAction(tr("Open &image volume…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open an image volume"), QString(),
        tr("Image volumes (*.vti *.nii *.nii.gz *.hdr *.mhd *.mha *.nrrd *.nhdr *.inr *.inr.gz "
           "*.mnc *.dcm *.ima);;All files (*)"));
    if (!path.isEmpty()) open_image_volume(path.toStdString());
  });
  file->addAction(tr("Open &DICOM folder…"), this, [this] {
    const QString path = QFileDialog::getExistingDirectory(this, tr("Open a DICOM series"));
    if (!path.isEmpty()) open_image_volume(path.toStdString());
  });
  recent_menu_ = file->addMenu(tr("Open &recent"));
  rebuild_recent_menu();
  file->addSeparator();
  file->addAction(tr("&Save"), this, [this] { save(); })->setShortcut(QKeySequence::Save);
  file->addAction(tr("Save &as…"), this, [this] { ask_save_as(); })
      ->setShortcut(QKeySequence::SaveAs);
  file->addSeparator();
  QMenu* view = menuBar()->addMenu(tr("&View"));  // filled below, after Training
  build_view_menu_items(file, view);
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close)->setShortcut(QKeySequence::Quit);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = document_.undo_stack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = document_.undo_stack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  QAction* remove = edit->addAction(tr("&Delete object"), this, [this] {
    const QString id = view_->selected_object();
    if (id.isEmpty()) return;
    try {
      document_.undo_stack()->push(new RemoveObjectCommand(document_, id.toStdString()));
    } catch (const std::exception& e) {
      show_error(QString::fromUtf8(e.what()));
    }
  });
  remove->setShortcut(QKeySequence::Delete);

  QMenu* create = menuBar()->addMenu(tr("&Create"));
  create->addAction(tr("&Ball…"), this, [this] { ask_create(PrimitiveKind::Ball); });
  create->addAction(tr("&Flat…"), this, [this] { ask_create(PrimitiveKind::Flat); });
  create->addAction(tr("&Pipe…"), this, [this] { ask_create(PrimitiveKind::Pipe); });
  create->addSeparator();
  create->addAction(tr("Generate &variants…"), this, [this] {
    VariantsDialog dialog(document_.scenario(), this);
    if (dialog.exec() == QDialog::Accepted) generate_variants(dialog.request());
  });

  QMenu* segment = menuBar()->addMenu(tr("&Segmentation"));
  segment->addAction(tr("&Downsample image volume…"), this, [this] {
    bool ok = false;
    const int factor = QInputDialog::getInt(this, tr("Downsample"),
                                            tr("Voxels merged along each axis"), 2, 1, 16, 1, &ok);
    if (ok) downsample_image_volume({factor, factor, factor});
  });
  segment->addAction(tr("Open &label map…"), this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open a label map"), QString(),
        tr("Label maps (*.vti *.nii *.nii.gz *.mha *.mhd *.nrrd);;All files (*)"));
    if (!path.isEmpty()) segmentation_->load_label_map(path.toStdString());
  });
  QAction* undo_step =
      segmentation_->history()->createUndoAction(this, tr("&Undo segmentation step"));
  undo_step->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_Z));
  segment->addAction(undo_step);
  segment->addAction(
      segmentation_->history()->createRedoAction(this, tr("&Redo segmentation step")));
  segment->addSeparator();
  segment->addAction(tr("&Mesh organ"), this,
                     [this] { segmentation_->mesh_segmentation(segmentation_->mesh_request()); });

  QMenu* training = menuBar()->addMenu(tr("&Training"));
  training->addAction(tr("&Launch…"), this, [this] {
    TrainingDialog dialog(this);
    if (dialog.exec() == QDialog::Accepted)
      launch_interactive_training(dialog.input(), dialog.duration());
  });
  training->addAction(tr("Launch &headless scripted run…"), this, [this] {
    const QString script =
        QFileDialog::getOpenFileName(this, tr("Script of the headless run (Cancel: no instrument)"),
                                     QString(), tr("Scripts (*.json);;All files (*)"));
    bool ok = false;
    const double duration = QInputDialog::getDouble(
        this, tr("Launch headless run"), tr("Session length in s (0: the script's or scenario's)"),
        0.0, 0.0, 3600.0, 1, &ok);
    if (ok) launch_training(duration, script);
  });
  training->addAction(tr("&Stop session"), this, [this] { launcher_.stop(); });

  menuBar()->removeAction(view->menuAction());
  menuBar()->addMenu(view);
  view->addAction(tr("&Reset camera"), this,
                  [this] { view_->show_scenario(document_.scenario(), document_.files(), true); });
  build_volume_menu(view);
}

void MainWindow::rebuild_recent_menu() {
  if (recent_menu_ == nullptr) return;
  recent_menu_->clear();
  for (const QString& path : recent_files()) {
    recent_menu_->addAction(path, this, [this, path] {
      if (maybe_save()) open_package(path.toStdString());
    });
  }
  recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

void MainWindow::ask_create(PrimitiveKind kind) {
  const QString what = QString::fromStdString(to_string(kind));
  const QString label = kind == PrimitiveKind::Flat ? tr("Edge length of the %1 in mm")
                                                    : tr("Radius of the %1 in mm");
  bool ok = false;
  const double size_mm = QInputDialog::getDouble(this, tr("Create %1").arg(what), label.arg(what),
                                                 20.0, 1.0, 500.0, 1, &ok);
  if (!ok) return;
  PrimitiveRequest request;
  request.kind = kind;
  request.size = size_mm / 1000.0;
  request.length = 4.0 * request.size;
  request.cell_size = kind == PrimitiveKind::Flat ? request.size / 20.0 : request.size / 3.0;
  create_primitive(request);
}

bool MainWindow::ask_save_as() {
  const QString path =
      QFileDialog::getSaveFileName(this, tr("Save the package"), QString(),
                                   tr("Package folder (*.vscene);;Zipped package (*.vscz)"));
  if (path.isEmpty()) return false;
  return save_as(path.toStdString());
}

}  // namespace viscera::studio
