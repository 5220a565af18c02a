// The studio's "Done when" (issue 9): the whole authoring path on the real main window under
// Xvfb, without the terminal — load a real image volume, segment and mesh an organ, add a
// pathology, a texture and vessels, generate variants, and launch a training session that returns a
// report.

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
#include "tests/studio_gui/liver_volume.h"

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

    // 1. A real image volume: CGAL's liver (438 × 353 × 165 voxels, libcgal-demo) through the
    // real INR reader, downsampled ×4 in-plane and ×2 across slices as Segmentation ▸ Downsample.
    QVERIFY(window.open_image_volume(studio_tests::cgal_liver(dir())));
    QVERIFY(window.downsample_image_volume({4, 4, 2}));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join("; ")));

    // 2. Threshold, grow the liver from a seed inside it, clean up and mesh it into an organ.
    studio::SegmentationPanel* segmentation = window.segmentation_panel();
    QVERIFY(segmentation->segment_threshold(128.0, 255.0, 1));
    const core::ImageVolume& image = segmentation->segmentation().volume();
    const std::array<int, 3> inside = studio_tests::deep_inside(image, {54, 44, 41});
    QVERIFY(inside[0] >= 0);
    const core::Vec3 seed = image.index_to_world(core::Vec3(inside[0], inside[1], inside[2]));
    QVERIFY(segmentation->grow_region_at(seed, 127.0, 2));
    QVERIFY(segmentation->open_labels(1));
    QVERIFY(segmentation->keep_largest());
    QVERIFY(segmentation->segmentation().voxel_count(2) > 50'000);
    studio::OrganMeshRequest mesh = segmentation->mesh_request();
    mesh.label = 2;
    mesh.name = "Liver";
    mesh.target_tets = 8000;
    mesh.triangles = 4000;
    const QString organ = segmentation->mesh_segmentation(mesh);
    QVERIFY2(!organ.isEmpty(), qPrintable(errors.join("; ")));
    window.select_object(organ);
    // The highest knot of the organ's body, where the polyp goes (so it is attached to knots
    // beside it, not across a coarse tet).
    const core::SceneObject* liver_object =
        window.document().scenario().find_object(organ.toStdString());
    QVERIFY(liver_object != nullptr && !liver_object->body.tets.empty());
    core::Vec3 top = liver_object->body.nodes.front();
    for (const auto& n : liver_object->body.nodes)
      if (n.z() > top.z()) top = n;

    // 3.–5. A polyp on top of the organ, a texture baked onto it and a vessel tree inside it.
    studio::OrganPanels* panels = window.organ_panels();
    const QString polyp = panels->pathologies()->place_pathology_on(organ, top, "polyp", 0.008);
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

    const templates::PatientValidation checked = templates::validate_patient_geometry(authored);
    QVERIFY2(checked.valid(), checked.first_failure().c_str());

    // 6. Variants of the scenario (no template): each validated.
    studio::VariantRequest request;
    request.source = studio::VariantSource::Scenario;
    request.count = 2;
    request.seed = 5;
    QVERIFY(window.generate_variants(request));
    QCOMPARE(window.variants_gallery()->count(), 2);
    for (int i = 0; i < 2; ++i) {
      const studio::Variant& v = window.variants_gallery()->variant(i);
      // The baked organ is cut at its UV seams; validation judges the welded surface.
      QVERIFY2(v.valid, v.failure.c_str());
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
