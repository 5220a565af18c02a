// The studio's image volume slice views, Cancel of background work and the New from template
// dialog, in the real main window under Xvfb (issue 9 §2, §9).
#include <QVTKOpenGLNativeWidget.h>
#include <vtkImageSliceMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkPropCollection.h>

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QTreeWidget>
#include <QtTest>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "core/materials/shipped_materials.h"
#include "core/package/scenario_package.h"
#include "studio/ui/background_task.h"
#include "studio/ui/main_window.h"
#include "studio/ui/material_panel.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/slice_views.h"
#include "studio/ui/template_dialog.h"
#include "templates/template_catalog.h"
#include "tests/studio_gui/image_checks.h"
#include "textures/scenario_baking.h"

namespace fs = std::filesystem;
using namespace viscera;
using namespace viscera::studio_tests;

class ViewsTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;

  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options() const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / "recovery";
    o.autosave_interval_ms = 100;
    o.simulator = QStringLiteral(VISCERA_BINARY_DIR "/bin/viscera-sim");
    return o;
  }

 private slots:
  void sliceViewsShowTheVolumeWithWindowLevel() {
    // 48 × 40 × 32 voxels of 2 mm, origin (-47, -39, -31) mm, a 30 mm sphere.
    const fs::path path = dir() / "sphere.vti";
    write_phantom(path, {48, 40, 32}, 0.03);

    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.open_image_volume(path));
    studio::SliceViews* slices = window.slice_views();
    QVERIFY(slices->isVisible());
    QCOMPARE(slices->slice(0), 24);
    QCOMPARE(slices->slice(1), 20);
    QCOMPARE(slices->slice(2), 16);
    QVERIFY(slices->window() > 1900.0);  // the full range, -1000 to about +1000
    QVERIFY(std::abs(slices->level()) < 50.0);
    // The axial plane is index slice k = 16, placed in the 3D view by the volume's geometry.
    vtkImageSlice* plane = slices->plane_in_3d(2);
    auto* mapper = vtkImageSliceMapper::SafeDownCast(plane->GetMapper());
    QVERIFY(mapper != nullptr);
    QCOMPARE(mapper->GetOrientation(), 2);
    QCOMPARE(mapper->GetSliceNumber(), 16);
    const double local[4] = {0.0, 0.0, 16 * 0.002, 1.0};
    double world[4];
    plane->GetMatrix()->MultiplyPoint(local, world);
    QVERIFY(std::abs(world[0] - (-0.047)) < 1e-12);
    QVERIFY(std::abs(world[2] - (-0.031 + 0.032)) < 1e-12);
    QVERIFY(window.scene_view()->renderer()->GetViewProps()->IsItemPresent(plane) != 0);

    QImage axial = slices->grab_view(2);
    const QPoint centre(axial.width() / 2, axial.height() / 2);
    QVERIFY(qGray(axial.pixel(centre)) > 200);
    QVERIFY(qGray(axial.pixel(2, 2)) < 60);
    QVERIFY(grey_deviation(axial) > 30.0);

    slices->set_window_level(10.0, 5000.0);  // everything below the window: black
    QVERIFY(grey_deviation(slices->grab_view(2)) < 2.0);
    slices->set_window_level(2000.0, 0.0);
    slices->set_slice(2, 0);  // below the sphere
    QCOMPARE(slices->slice(2), 0);
    axial = slices->grab_view(2);
    QVERIFY(qGray(axial.pixel(centre)) < 60);
    slices->set_slice(2, 99);
    QCOMPARE(slices->slice(2), 31);

    const fs::path broken = dir() / "broken.vti";
    std::ofstream(broken) << "<VTKFile type=\"ImageData\">";
    QVERIFY(!window.open_image_volume(broken));
    QCOMPARE(errors.size(), 1);
    QVERIFY(!errors[0].contains('\n'));
    QCOMPARE(slices->slice(2), 31);  // the shown volume stays
  }

  void cancelStopsBackgroundWork() {
    studio::MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTimer::singleShot(600, &window, [&window] {
      // The user presses the dialog's Cancel button.
      auto* dialog = window.findChild<QProgressDialog*>();
      auto* button = dialog != nullptr ? dialog->findChild<QPushButton*>() : nullptr;
      if (button != nullptr) button->click();
    });
    QElapsedTimer clock;
    clock.start();
    const std::exception_ptr error =
        studio::run_in_background(&window, "spinning", [](core::Progress& progress) {
          progress.begin_stage("spinning", std::int64_t{1} << 40);
          for (;;) {
            progress.step();
            QThread::usleep(100);
          }
        });
    QVERIFY(clock.elapsed() < 10'000);
    QVERIFY(error != nullptr);
    QVERIFY_EXCEPTION_THROWN(std::rethrow_exception(error), core::CancelledError);
  }

  void newFromTemplateUsesTheDialogsParameters() {
    studio::TemplateDialog dialog;
    QVERIFY(dialog.select_template("ball"));
    QVERIFY(dialog.overrides().empty());
    QVERIFY(dialog.set_parameter("radius", 0.025));
    QVERIFY(dialog.set_parameter("cell_size", 0.01));
    QVERIFY(!dialog.set_parameter("no-such-parameter", 1.0));
    dialog.set_seed(7);
    const auto overrides = dialog.overrides();
    QCOMPARE(overrides.size(), std::size_t{2});
    QCOMPARE(overrides.at("radius"), std::string("0.025"));

    studio::MainWindow window(options());
    QVERIFY(window.new_from_template(dialog.template_name(), overrides, dialog.seed()));
    const core::Scenario& scenario = window.document().scenario();
    QCOMPARE(scenario.provenance.seed, std::uint64_t{7});
    const core::BoundingBox box = core::bounds(scenario.find_object("ball")->surface);
    QVERIFY(std::abs(box.max.z() - 0.025) < 1e-6);
    QVERIFY(window.isWindowModified());
    QVERIFY(window.windowTitle().startsWith("untitled"));
    // The same template, parameters and seed through the library give the same scenario.
    core::Scenario direct = templates::build_from_template("ball", overrides, 7);
    QCOMPARE(direct.objects.size(), scenario.objects.size());
    QVERIFY(direct.objects[0].surface == scenario.objects[0].surface);
  }
};

int run_views_test(int argc, char** argv) {
  ViewsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "views_test.moc"
