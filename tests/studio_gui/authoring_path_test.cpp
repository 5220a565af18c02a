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
#include "core/segmentation/threshold.h"
#include "importers/meshing/label_body.h"
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
