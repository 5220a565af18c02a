// The asset library browser (issue 9 §7) on the real main window under Xvfb: adding the selected
// object and material, listing with type filter, search and thumbnails, and drops of library
// entries (constructed QDropEvents through the same event filter a drag ends in) onto the 3D
// view and the scene tree.

#include "studio/ui/library_browser.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QListWidget>
#include <QMimeData>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>
#include <filesystem>
#include <memory>

#include "core/library/asset_library.h"
#include "core/materials/shipped_materials.h"
#include "studio/document/asset_payloads.h"
#include "studio/ui/main_window.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"

namespace fs = std::filesystem;
using namespace viscera;

namespace {

/// Sends a drop of `mime` at `at` to `widget`, as a finished drag does; returns its acceptance.
bool drop_on(QWidget* widget, const QMimeData* mime, const QPoint& at) {
  QDragEnterEvent enter(at, Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(widget, &enter);
  if (!enter.isAccepted()) return false;
  QDropEvent drop(QPointF(at), Qt::CopyAction, mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(widget, &drop);
  return drop.isAccepted();
}

}  // namespace

class LibraryBrowserTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;
  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options(const std::string& library) const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / "recovery";
    o.library = (dir() / library).string();
    return o;
  }

 private slots:
  void listingNeverCreatesALibrary() {
    studio::MainWindow window(options("none.sqlite"));
    QVERIFY(window.library_browser()->shown_names().isEmpty());
    QVERIFY(!fs::exists(dir() / "none.sqlite"));
  }

  void addsTheSelectedObjectAndMaterialAndFiltersThem() {
    studio::MainWindow window(options("add.sqlite"));
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    QVERIFY(window.new_from_template("ball", {{"cell_size", "0.012"}}, 1));
    window.select_object("ball");
    QVERIFY(window.add_selected_object_to_library("ball-model"));
    QVERIFY(window.add_selected_material_to_library("ball-tissue"));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join("; ")));

    studio::LibraryBrowser* browser = window.library_browser();
    QCOMPARE(browser->shown_names(), QStringList({"ball-model", "ball-tissue"}));
    QVERIFY(!browser->list()->item(0)->icon().isNull());  // the model's surface thumbnail
    browser->set_type_filter(core::AssetType::Material);
    QCOMPARE(browser->shown_names(), QStringList({"ball-tissue"}));
    browser->set_type_filter(std::nullopt);
    browser->set_search("MODEL");
    QCOMPARE(browser->shown_names(), QStringList({"ball-model"}));
    browser->set_search("");

    // What the library holds reads back as the same object and material.
    const core::AssetLibrary library(dir() / "add.sqlite");
    QCOMPARE(library.list().size(), std::size_t{2});
    const core::Scenario& scenario = window.document().scenario();
    const studio::ModelParts parts =
        studio::model_parts_from_asset(library.get("ball-model"), core::Scenario{});
    QCOMPARE(parts.objects.size(), std::size_t{1});
    QVERIFY(parts.objects[0] == scenario.objects[0]);
    QVERIFY(studio::material_from_asset(library.get("ball-tissue")) ==
            scenario.materials.at(scenario.objects[0].material));

    // A drag out of the list carries the entry under the custom mime type.
    const QModelIndexList rows = {browser->list()->model()->index(0, 0)};
    std::unique_ptr<QMimeData> mime(browser->list()->model()->mimeData(rows));
    QVERIFY(mime && mime->hasFormat(studio::kAssetMimeType));
    const auto ref = studio::asset_from_mime(mime.get());
    QVERIFY(ref.has_value());
    QCOMPARE(ref->name, std::string("ball-model"));
    QCOMPARE(ref->version, 1);
    QVERIFY(ref->type == core::AssetType::Model);
  }

  void droppedModelIsOneUndoableCommand() {
    studio::MainWindow window(options("drop.sqlite"));
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.new_from_template("ball", {{"cell_size", "0.012"}}, 1));
    window.select_object("ball");
    QVERIFY(window.add_selected_object_to_library("ball-model"));
    const core::Scenario before = window.document().scenario();
    const int steps = window.document().undo_stack()->count();

    // Plain text is not ours: the view does not take it.
    QMimeData text;
    text.setText("ball-model");
    QVERIFY(!drop_on(window.scene_view(), &text, {20, 20}));

    std::unique_ptr<QMimeData> mime(
        studio::asset_mime_data(dir() / "drop.sqlite", window.library_browser()->summary(0)));
    QVERIFY(drop_on(window.scene_view(), mime.get(), {20, 20}));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join("; ")));
    const core::Scenario& after = window.document().scenario();
    QCOMPARE(after.objects.size(), std::size_t{2});
    QCOMPARE(after.objects[1].id, std::string("ball-2"));
    QVERIFY(after.objects[1].surface == before.objects[0].surface);
    QVERIFY(after.objects[1].body == before.objects[0].body);
    QCOMPARE(window.document().undo_stack()->count(), steps + 1);
    QVERIFY(window.scene_tree()->object_item("ball-2") != nullptr);
    window.document().undo_stack()->undo();
    QVERIFY(window.document().scenario() == before);
    window.document().undo_stack()->redo();
    QCOMPARE(window.document().scenario().objects.size(), std::size_t{2});
  }

  void droppedMaterialIsAssignedToTheObjectUnderTheCursor() {
    studio::MainWindow window(options("material.sqlite"));
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.new_from_template("ball", {{"cell_size", "0.012"}}, 1));
    const core::Material liver = core::shipped_material("liver");
    core::AssetLibrary(dir() / "material.sqlite").add(studio::material_asset_entry(liver, "liver"));
    window.library_browser()->refresh();
    QCOMPARE(window.library_browser()->shown_names(), QStringList({"liver"}));
    std::unique_ptr<QMimeData> mime(
        studio::asset_mime_data(dir() / "material.sqlite", window.library_browser()->summary(0)));

    // On empty space of the tree: nothing to assign to, one error line.
    QTreeWidget* tree = window.scene_tree();
    QVERIFY(!drop_on(tree->viewport(), mime.get(), {5, tree->viewport()->height() - 5}));
    QCOMPARE(errors.size(), 1);
    QVERIFY(window.document().scenario().find_object("ball")->material != "liver");

    // On the ball's row: assigned, undoable.
    const QPoint row = tree->visualItemRect(window.scene_tree()->object_item("ball")).center();
    const int steps = window.document().undo_stack()->count();
    QVERIFY(drop_on(tree->viewport(), mime.get(), row));
    QCOMPARE(window.document().scenario().find_object("ball")->material, std::string("liver"));
    QVERIFY(window.document().scenario().materials.at("liver") == liver);
    QCOMPARE(window.document().undo_stack()->count(), steps + 1);
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-library-tests"));
  LibraryBrowserTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "library_browser_test.moc"
