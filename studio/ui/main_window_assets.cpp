// The main window's asset docks (issue 9 §6–7): the variants gallery and the asset library
// browser, with what opens a variant, adds to the library and takes drops from it.

#include <QDockWidget>
#include <QMimeData>
#include <QStatusBar>

#include "core/error.h"
#include "studio/document/add_model_command.h"
#include "studio/document/asset_payloads.h"
#include "studio/document/document_commands.h"
#include "studio/ui/asset_drop.h"
#include "studio/ui/background_task.h"
#include "studio/ui/library_browser.h"
#include "studio/ui/main_window.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/variants_gallery.h"

namespace viscera::studio {

void MainWindow::build_asset_docks() {
  variants_ = new VariantsGallery(this);
  variants_dock_ = new QDockWidget(tr("Variants"), this);
  variants_dock_->setObjectName("variants-dock");
  variants_dock_->setWidget(variants_);
  addDockWidget(Qt::BottomDockWidgetArea, variants_dock_);
  variants_dock_->hide();
  connect(variants_, &VariantsGallery::open_requested, this, &MainWindow::open_variant);

  std::filesystem::path library_path;
  try {
    library_path = core::resolve_library_path(options_.library);
  } catch (const std::exception&) {
    // No HOME and no XDG: the browser shows the error when it cannot open "".
  }
  library_ = new LibraryBrowser(library_path, this);
  auto* library_dock = new QDockWidget(tr("Asset library"), this);
  library_dock->setObjectName("library-dock");
  library_dock->setWidget(library_);
  addDockWidget(Qt::LeftDockWidgetArea, library_dock);
  connect(library_, &LibraryBrowser::add_object_requested, this,
          [this] { add_selected_object_to_library(); });
  connect(library_, &LibraryBrowser::add_material_requested, this,
          [this] { add_selected_material_to_library(); });

  const auto drop = [this](const QMimeData* mime, const QString& target) {
    return drop_asset(mime, target);
  };
  new AssetDropFilter(
      view_, [this](const QPoint& p) { return view_->object_at(p); }, drop);
  new AssetDropFilter(
      tree_->viewport(),
      [this](const QPoint& p) {
        const QTreeWidgetItem* item = tree_->itemAt(p);
        return item != nullptr ? item->data(0, SceneTree::kObjectRole).toString() : QString();
      },
      drop);
}

bool MainWindow::generate_variants(const VariantRequest& request) {
  const core::Scenario base = document_.scenario();
  const PackageFiles files =
      request.source == VariantSource::Scenario ? document_.files() : PackageFiles{};
  std::vector<GalleryEntry> entries;
  if (!run(tr("Generating %1 variants").arg(request.count), [&](core::Progress& progress) {
        for (Variant& v : studio::generate_variants(base, request, progress)) {
          QImage thumbnail = v.scenario ? scenario_thumbnail(*v.scenario) : QImage();
          if (thumbnail.isNull()) {
            thumbnail = QImage(128, 128, QImage::Format_RGB888);
            thumbnail.fill(QColor(40, 44, 52));
          }
          entries.push_back({std::move(v), std::move(thumbnail)});
        }
      })) {
    return false;
  }
  const QString source =
      request.source == VariantSource::Template
          ? tr("template %1").arg(QString::fromStdString(base.provenance.template_name))
          : tr("this scenario");
  variants_->set_variants(
      std::move(entries), files,
      tr("%1 variants of %2, seed %3").arg(request.count).arg(source).arg(request.seed));
  variants_dock_->show();
  variants_dock_->raise();
  statusBar()->showMessage(tr("Generated %1 variants").arg(request.count), 5'000);
  return true;
}

bool MainWindow::open_variant(int row) {
  if (row < 0 || row >= variants_->count()) return false;
  const Variant& variant = variants_->variant(row);
  if (!variant.scenario) {
    show_error(tr("Variant %1 has no patient to open: %2")
                   .arg(variant.index)
                   .arg(QString::fromStdString(variant.failure)));
    return false;
  }
  if (!maybe_save()) return false;
  document_.reset({*variant.scenario, variants_->files()});
  statusBar()->showMessage(tr("Opened variant %1").arg(variant.index), 5'000);
  return true;
}

bool MainWindow::add_selected_object_to_library(const std::string& name) {
  const std::string id = view_->selected_object().toStdString();
  if (id.empty()) {
    show_error(tr("Select an object to add to the library."));
    return false;
  }
  const DocumentContent snapshot = document_.content();
  const std::filesystem::path path = library_->library_path();
  if (!run(tr("Adding %1 to the library").arg(QString::fromStdString(id)), [&](core::Progress&) {
        core::AssetLibrary(path).add(object_asset_entry(snapshot, id, name.empty() ? id : name));
      }))
    return false;
  library_->refresh();
  return true;
}

bool MainWindow::add_selected_material_to_library(const std::string& name) {
  const core::SceneObject* object =
      document_.scenario().find_object(view_->selected_object().toStdString());
  if (object == nullptr || !document_.scenario().materials.contains(object->material)) {
    show_error(tr("Select an object with a material to add it to the library."));
    return false;
  }
  const core::Material material = document_.scenario().materials.at(object->material);
  try {
    core::AssetLibrary(library_->library_path())
        .add(material_asset_entry(material, name.empty() ? material.id : name));
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return false;
  }
  library_->refresh();
  return true;
}

bool MainWindow::drop_asset(const QMimeData* mime, const QString& target) {
  const auto ref = asset_from_mime(mime);
  if (!ref) return false;
  try {
    if (ref->type == core::AssetType::Material) {
      if (target.isEmpty()) {
        show_error(tr("Drop the material %1 on an object to assign it.")
                       .arg(QString::fromStdString(ref->name)));
        return false;
      }
      const core::Material material =
          material_from_asset(core::AssetLibrary(ref->library).get(ref->name, ref->version));
      document_.undo_stack()->push(
          new AssignMaterialCommand(document_, target.toStdString(), material));
      select_object(target);
      return true;
    }
    if (ref->type != core::AssetType::Model) {
      show_error(tr("Only models and materials can be dropped into the scene; %1 is a %2.")
                     .arg(QString::fromStdString(ref->name))
                     .arg(QString::fromStdString(core::to_string(ref->type))));
      return false;
    }
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return false;
  }
  const core::Scenario target_scenario = document_.scenario();
  ModelParts parts;
  if (!run(tr("Adding %1").arg(QString::fromStdString(ref->name)), [&](core::Progress&) {
        parts = model_parts_from_asset(
            core::AssetLibrary(ref->library).get(ref->name, ref->version), target_scenario);
      }))
    return false;
  const QString first = QString::fromStdString(parts.objects.empty() ? "" : parts.objects[0].id);
  try {
    document_.undo_stack()->push(
        new AddModelCommand(document_, std::move(parts), QString::fromStdString(ref->name)));
  } catch (const std::exception& e) {
    show_error(QString::fromUtf8(e.what()));
    return false;
  }
  select_object(first);
  return true;
}

}  // namespace viscera::studio
