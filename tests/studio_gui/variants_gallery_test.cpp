// "Generate variants…" and the variants gallery (issue 9 §6) on the real main window under
// Xvfb: template variants through the variant generator, scenario variants through the smooth
// deformation, validation badges and tooltips, Cancel, and double-click opening a variant as a
// new document after asking to save the current one.

#include "studio/ui/variants_gallery.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QListWidget>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <filesystem>

#include "core/error.h"
#include "core/materials/shipped_materials.h"
#include "studio/document/document_commands.h"
#include "studio/document/variant_batch.h"
#include "studio/ui/main_window.h"
#include "templates/generator/patient_seed.h"

namespace fs = std::filesystem;
using namespace viscera;

namespace {

/// Clicks `button` on the next message box that opens.
void answer_next_message_box(QMessageBox::StandardButton button) {
  QTimer::singleShot(200, [button] {
    for (QWidget* w : QApplication::topLevelWidgets()) {
      if (auto* box = qobject_cast<QMessageBox*>(w); box != nullptr && box->isVisible()) {
        box->button(button)->click();
        return;
      }
    }
  });
}

/// The badge's colour: the pixel at the centre of the icon's top-right badge.
QColor badge_colour(const QListWidgetItem* item) {
  const QImage image = item->icon().pixmap(128, 128).toImage();
  const int r = std::max(8, image.width() / 7);
  return image.pixelColor(image.width() - r - 3, 3 + r / 3);
}

}  // namespace

class VariantsGalleryTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;
  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options() const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / "recovery";
    o.library = (dir() / "library.sqlite").string();
    return o;
  }

 private slots:
  void templateVariantsComeFromTheVariantGenerator() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    QVERIFY(window.new_from_template("urethra", {}, 1));
    QVERIFY(studio::has_template_source(window.document().scenario()));

    studio::VariantRequest request;
    request.source = studio::VariantSource::Template;
    request.count = 2;
    request.seed = 3;
    QVERIFY(window.generate_variants(request));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join("; ")));
    studio::VariantsGallery* gallery = window.variants_gallery();
    QCOMPARE(gallery->count(), 2);
    QVERIFY(gallery->isVisibleTo(&window));
    const studio::Variant& first = gallery->variant(0);
    const studio::Variant& second = gallery->variant(1);
    QVERIFY(first.valid && second.valid);
    QVERIFY(first.scenario && second.scenario);
    // Built by the template with its provenance, seeded as `viscera generate` seeds patient k.
    QCOMPARE(first.scenario->provenance.template_name, std::string("urethra"));
    QCOMPARE(first.draw_seed, templates::patient_seed("urethra", 3, 0, first.attempts - 1));
    QVERIFY(first.scenario->provenance.parameters != second.scenario->provenance.parameters);
    QVERIFY(gallery->tooltip(0).contains("passed every check"));
    const QColor badge = badge_colour(gallery->list()->item(0));
    QVERIFY2(badge.green() > 120 && badge.red() < 100, qPrintable(badge.name()));
    // The same request again gives the same patients.
    const studio::Variant again =
        studio::generate_variant(window.document().scenario(), request, 1);
    QVERIFY(again.scenario == second.scenario);
  }

  void scenarioVariantsShowFailedChecks() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    QVERIFY(window.new_from_template("ball", {{"cell_size", "0.012"}}, 1));
    // The ball template has no variability rules: its documents vary as scenarios.
    QVERIFY(!studio::has_template_source(window.document().scenario()));
    studio::VariantRequest request;
    request.source = studio::VariantSource::Template;
    QVERIFY(!window.generate_variants(request));
    QCOMPARE(errors.size(), 1);
    request.source = studio::VariantSource::Scenario;
    request.count = 3;
    request.seed = 9;
    QVERIFY(window.generate_variants(request));
    studio::VariantsGallery* gallery = window.variants_gallery();
    QCOMPARE(gallery->count(), 3);
    for (int i = 0; i < 3; ++i) {
      QVERIFY2(gallery->variant(i).valid, gallery->variant(i).failure.c_str());
      QVERIFY(gallery->variant(i).validation.at("drawn").contains("lipschitz_bound"));
      const core::Provenance& provenance = gallery->variant(i).scenario->provenance;
      QVERIFY(provenance.template_name.empty());
      QCOMPARE(provenance.seed, gallery->variant(i).draw_seed);
      QCOMPARE(provenance.parameters.at("base_template").get<std::string>(), std::string("ball"));
    }
    const auto& a = gallery->variant(0).scenario->objects[0].surface.vertices;
    const auto& b = gallery->variant(1).scenario->objects[0].surface.vertices;
    const auto& base = window.document().scenario().objects[0].surface.vertices;
    QVERIFY(a != b && a != base);
    // Thumbnails show the varied shapes: two variants' pictures differ.
    QVERIFY(studio::scenario_thumbnail(*gallery->variant(0).scenario) !=
            studio::scenario_thumbnail(*gallery->variant(1).scenario));

    // Bounds no tet mesh meets: every variant fails the "tets" check after its single draw.
    request.max_attempts = 1;
    request.validation.min_dihedral_degrees = 89.0;
    QVERIFY(window.generate_variants(request));
    QCOMPARE(gallery->count(), 3);
    for (int i = 0; i < 3; ++i) {
      QVERIFY(!gallery->variant(i).valid);
      QCOMPARE(gallery->variant(i).failed_check, std::string("tets"));
      QVERIFY2(gallery->tooltip(i).contains("failed tets:"), qPrintable(gallery->tooltip(i)));
      QCOMPARE(gallery->list()->item(i)->toolTip(), gallery->tooltip(i));
    }
    const QColor badge = badge_colour(gallery->list()->item(0));
    QVERIFY2(badge.red() > 150 && badge.green() < 100, qPrintable(badge.name()));
  }

  void cancelLeavesTheGalleryAsItWas() {
    studio::MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.new_from_template("ball", {{"cell_size", "0.012"}}, 1));
    QTimer::singleShot(700, &window, [&window] {
      auto* dialog = window.findChild<QProgressDialog*>();
      auto* button = dialog != nullptr ? dialog->findChild<QPushButton*>() : nullptr;
      if (button != nullptr) button->click();
    });
    studio::VariantRequest request;
    request.source = studio::VariantSource::Scenario;
    request.count = 200;
    QElapsedTimer clock;
    clock.start();
    QVERIFY(!window.generate_variants(request));
    QVERIFY(clock.elapsed() < 10'000);
    QCOMPARE(window.variants_gallery()->count(), 0);
  }

  void doubleClickOpensAVariantAfterAskingToSave() {
    studio::MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.new_from_template("ball", {{"cell_size", "0.012"}}, 1));
    studio::VariantRequest request;
    request.source = studio::VariantSource::Scenario;
    request.count = 2;
    QVERIFY(window.generate_variants(request));
    window.document().undo_stack()->push(new studio::AssignMaterialCommand(
        window.document(), "ball", core::shipped_material("liver")));
    const core::Scenario edited = window.document().scenario();

    QListWidget* list = window.variants_gallery()->list();
    const QPoint at = list->visualItemRect(list->item(1)).center();
    // Cancel keeps the edited document.
    answer_next_message_box(QMessageBox::Cancel);
    QTest::mouseDClick(list->viewport(), Qt::LeftButton, {}, at);
    QVERIFY(window.document().scenario() == edited);
    // Discard opens the variant as a new, unsaved document without undo history.
    QTest::qWait(QApplication::doubleClickInterval() + 50);  // not a triple click
    answer_next_message_box(QMessageBox::Discard);
    QTest::mouseDClick(list->viewport(), Qt::LeftButton, {}, at);
    QVERIFY(window.document().scenario() == *window.variants_gallery()->variant(1).scenario);
    QVERIFY(window.document().is_dirty());
    QVERIFY(window.document().path().empty());
    QCOMPARE(window.document().undo_stack()->count(), 0);
    // A variant is a complete package: it saves and reads back as it is.
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    QVERIFY2(window.save_as(dir() / "variant.vscene"), qPrintable(errors.join("; ")));
    const core::Scenario opened = window.document().scenario();
    QVERIFY(window.open_package(dir() / "variant.vscene"));
    QVERIFY(window.document().scenario().provenance == opened.provenance);
    QCOMPARE(window.document().scenario().objects.size(), opened.objects.size());
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-variants-tests"));
  VariantsGalleryTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "variants_gallery_test.moc"
