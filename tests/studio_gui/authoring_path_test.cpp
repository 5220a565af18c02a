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

#include "core/materials/shipped_materials.h"
#include "core/mesh/surface_embedding.h"
#include "core/segmentation/threshold.h"
#include "importers/meshing/label_body.h"
#include "importers/volume/volume_reader.h"
#include "studio/document/document_commands.h"
#include "studio/ui/main_window.h"
#include "studio/ui/variants_gallery.h"
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

    // 2. The organ: threshold the bright sphere and mesh it (surface, tets, embedding), added as
    //    one undoable command. (Library calls until the segmentation panel is on main.)
    {
      const core::LabelMap labels =
          core::threshold(importers::read_volume(volume).volume, 0.0, 2000.0, 1);
      importers::LabelBodyOptions meshing;
      meshing.tets.cell_size = 0.008;
      const importers::LabelBody body =
          importers::mesh_label_body(labels, meshing, volume.string());
      const core::Material tissue = core::shipped_material("myometrium");
      core::SceneObject organ;
      organ.id = "organ";
      organ.name = "Organ";
      organ.material = tissue.id;
      organ.body_kind = core::BodyKind::TetMesh;
      organ.surface = body.surface.mesh;
      organ.body = body.body;
      organ.body.node_mass = core::lumped_node_masses(organ.body, tissue.density);
      organ.embedding = body.embedding;
      window.document().undo_stack()->push(
          new studio::AddObjectCommand(window.document(), organ, tissue));
    }
    QCOMPARE(window.document().scenario().objects.size(), std::size_t{1});

    // 6. Variants of the scenario (no template): each validated.
    studio::VariantRequest request;
    request.source = studio::VariantSource::Scenario;
    request.count = 2;
    request.seed = 5;
    QVERIFY(window.generate_variants(request));
    QCOMPARE(window.variants_gallery()->count(), 2);
    for (int i = 0; i < 2; ++i)
      QVERIFY2(window.variants_gallery()->variant(i).valid,
               window.variants_gallery()->variant(i).failure.c_str());

    // 7. A headless training session of the authored scenario returns its report.
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
