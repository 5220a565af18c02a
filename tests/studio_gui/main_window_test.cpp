// Drives the real studio main window under Xvfb (issue 9 §10): open a package, create a ball,
// change its material, undo and redo, save and reopen; pick in 3D; errors keep the document;
// crash recovery; a headless training session and its report; a screenshot that is not blank.

#include "studio/ui/main_window.h"

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
#include "studio/ui/material_panel.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/slice_views.h"
#include "studio/ui/template_dialog.h"
#include "templates/template_catalog.h"
#include "textures/scenario_baking.h"

namespace fs = std::filesystem;
using namespace viscera;

namespace {

/// Share of pixels of `image` whose red exceeds blue by 30: organ tissue, not background.
double tissue_share(const QImage& image) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  std::int64_t tissue = 0;
  for (int y = 0; y < rgb.height(); ++y) {
    for (int x = 0; x < rgb.width(); ++x) {
      const QRgb p = rgb.pixel(x, y);
      if (qRed(p) > qBlue(p) + 30) ++tissue;
    }
  }
  return static_cast<double>(tissue) / (static_cast<double>(rgb.width()) * rgb.height());
}

/// Standard deviation of the grey levels of `image`.
double grey_deviation(const QImage& image) {
  const QImage grey = image.convertToFormat(QImage::Format_Grayscale8);
  double sum = 0.0, sum2 = 0.0;
  for (int y = 0; y < grey.height(); ++y) {
    const uchar* row = grey.constScanLine(y);
    for (int x = 0; x < grey.width(); ++x) {
      sum += row[x];
      sum2 += static_cast<double>(row[x]) * row[x];
    }
  }
  const double n = static_cast<double>(grey.width()) * grey.height();
  return std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
}

/// A CT-like int16 volume of 2 mm voxels centred on the origin: a sphere of `radius` m whose
/// values fall from +1000 HU at the centre to +500 HU at its rim, in -1000 HU air.
void write_phantom(const fs::path& path, std::array<int, 3> dims, double radius) {
  core::ImageVolume volume;
  volume.dims = dims;
  volume.spacing = core::Vec3::Constant(0.002);
  volume.origin = -0.001 * core::Vec3(dims[0] - 1, dims[1] - 1, dims[2] - 1);
  volume.scalar_type = core::ScalarType::Int16;
  volume.allocate();
  auto* voxels = reinterpret_cast<std::int16_t*>(volume.voxels.data());
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) {
        const double r = volume.index_to_world(core::Vec3(i, j, k)).norm();
        voxels[volume.linear_index(i, j, k)] =
            static_cast<std::int16_t>(r < radius ? 1000.0 - 500.0 * r / radius : -1000.0);
      }
  core::write_volume_vti(volume, path);
}

}  // namespace

class MainWindowTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;
  fs::path ball_package_;
  fs::path textured_package_;
  fs::path out_dir_;

  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options(const std::string& recovery = "recovery") const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / recovery;
    o.autosave_interval_ms = 100;
    o.simulator = QStringLiteral(VISCERA_BINARY_DIR "/bin/viscera-sim");
    return o;
  }

 private slots:
  void initTestCase() {
    QVERIFY(tmp_.isValid());
    const char* out = std::getenv("VISCERA_TEST_TMP");
    out_dir_ = out != nullptr ? fs::path(out) : dir();
    fs::create_directories(out_dir_);
    core::Scenario scenario = templates::build_from_template("ball", {{"cell_size", "0.012"}}, 1);
    ball_package_ = dir() / "ball.vscene";
    core::write_package(scenario, ball_package_);

    // The same ball with a baked endometrium texture, for the textured view and the screenshot.
    core::TextureSpec skin;
    skin.id = "skin";
    skin.preset = "endometrium";
    skin.seed = 3;
    skin.width = skin.height = 256;
    scenario.textures[skin.id] = skin;
    scenario.objects[0].texture = skin.id;
    const textures::BakedTextures baked = textures::bake_textures_into(scenario, {});
    textured_package_ = dir() / "textured.vscene";
    core::write_package(scenario, baked.files, textured_package_);
  }

  void authorsUndoesRedoesSavesAndReopens() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    QVERIFY(window.open_package(ball_package_));
    QVERIFY(window.windowTitle().startsWith("ball.vscene"));
    QVERIFY(!window.isWindowModified());
    QVERIFY(window.scene_tree()->object_item("ball") != nullptr);
    QVERIFY(window.scene_view()->object_visible("ball"));
    const core::Scenario opened = window.document().scenario();
    QVERIFY(window.recent_files().contains(QString::fromStdString(fs::absolute(ball_package_))));

    studio::PrimitiveRequest request;
    request.center = core::Vec3(0.07, 0.0, 0.0);
    request.size = 0.015;
    request.cell_size = 0.006;
    QVERIFY(window.create_primitive(request));
    QCOMPARE(window.document().scenario().objects.size(), std::size_t{2});
    QCOMPARE(window.scene_view()->selected_object(), QString("ball-2"));
    QVERIFY(window.scene_tree()->object_item("ball-2")->isSelected());
    QVERIFY(window.isWindowModified());
    const core::SceneObject* created = window.document().scenario().find_object("ball-2");
    QCOMPARE(created->material, std::string("soft-tissue"));
    QVERIFY(created->body.tets.size() > 100);
    const core::Scenario after_create = window.document().scenario();

    studio::MaterialPanel* panel = window.material_panel();
    const int liver = panel->picker()->findData("liver");
    QVERIFY(liver >= 0);
    QVERIFY(panel->choose_material("liver"));
    QCOMPARE(window.document().scenario().find_object("ball-2")->material, std::string("liver"));
    QCOMPARE(panel->picker()->currentData().toString(), QString("liver"));
    const core::Scenario after_material = window.document().scenario();
    const double shipped_density = core::shipped_material("liver").density;
    QCOMPARE(panel->field_editor(studio::MaterialField::Density)->value(), shipped_density);

    panel->field_editor(studio::MaterialField::Density)->setValue(1111.0);
    QCOMPARE(window.document().scenario().materials.at("liver").density, 1111.0);
    const core::Scenario after_density = window.document().scenario();

    auto* stack = window.document().undo_stack();
    QCOMPARE(stack->count(), 3);
    stack->undo();
    QVERIFY(window.document().scenario() == after_material);
    QCOMPARE(panel->field_editor(studio::MaterialField::Density)->value(), shipped_density);
    stack->undo();
    QVERIFY(window.document().scenario() == after_create);
    stack->undo();
    QVERIFY(window.document().scenario() == opened);
    QVERIFY(window.scene_tree()->object_item("ball-2") == nullptr);
    QVERIFY(!window.isWindowModified());
    stack->redo();
    stack->redo();
    stack->redo();
    QVERIFY(window.document().scenario() == after_density);
    QVERIFY(window.scene_tree()->object_item("ball-2") != nullptr);
    QVERIFY(window.isWindowModified());

    const fs::path saved = dir() / "authored.vscene";
    QVERIFY(window.save_as(saved));
    QVERIFY(window.windowTitle().startsWith("authored.vscene"));
    QVERIFY(!window.isWindowModified());
    QVERIFY(core::validate_package(saved).empty());

    studio::MainWindow reopened(options("recovery-reopen"));
    reopened.set_error_handler([&](const QString& m) { errors << m; });
    QVERIFY(reopened.open_package(saved));
    QVERIFY(reopened.document().scenario() == after_density);
    QCOMPARE(reopened.document().scenario().materials.at("liver").density, 1111.0);
    QVERIFY(errors.isEmpty());
  }

  void pickingAndTreeStayInStep() {
    studio::MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.open_package(ball_package_));
    studio::SceneView* view = window.scene_view();
    QTest::qWait(50);

    QTest::mouseClick(view, Qt::LeftButton, {}, view->rect().center());
    QCOMPARE(view->selected_object(), QString("ball"));
    QVERIFY(window.scene_tree()->object_item("ball")->isSelected());
    QVERIFY(window.material_panel()->isEnabled());

    QTest::mouseClick(view, Qt::LeftButton, {}, QPoint(3, 3));
    QCOMPARE(view->selected_object(), QString());
    QVERIFY(window.scene_tree()->selectedItems().isEmpty());

    window.scene_tree()->object_item("ball")->setSelected(true);
    QCOMPARE(view->selected_object(), QString("ball"));
    window.scene_tree()->object_item("ball")->setCheckState(0, Qt::Unchecked);
    QVERIFY(!view->object_visible("ball"));
    QCOMPARE(view->object_at(view->rect().center()), QString());
    window.scene_tree()->object_item("ball")->setCheckState(0, Qt::Checked);
    QVERIFY(view->object_visible("ball"));
  }

  void errorsLeaveTheDocumentIntact() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    QVERIFY(window.open_package(ball_package_));
    const core::Scenario before = window.document().scenario();
    const fs::path broken = dir() / "broken.vscene";
    fs::create_directories(broken);
    std::ofstream(broken / "manifest.json") << "{\"format\": \"viscera-scenario\", \"version\": 1}";
    QVERIFY(!window.open_package(broken));
    QCOMPARE(errors.size(), 1);
    QVERIFY(!errors[0].contains('\n'));
    QVERIFY(errors[0].contains("manifest.json"));
    QVERIFY(window.document().scenario() == before);
    QCOMPARE(window.document().path(), ball_package_);

    studio::PrimitiveRequest bad;
    bad.size = -0.01;
    QVERIFY(!window.create_primitive(bad));
    QCOMPARE(errors.size(), 2);
    QVERIFY(window.document().scenario() == before);
    QCOMPARE(window.document().undo_stack()->count(), 0);
  }

  void recoversAfterACrash() {
    const fs::path recovery = dir() / "recovery-crash";
    core::Scenario unsaved;
    {
      auto crashed = std::make_unique<studio::MainWindow>(options("recovery-crash"));
      QVERIFY(crashed->open_package(ball_package_));
      QSignalSpy autosaved(&crashed->autosave(), &studio::Autosave::autosaved);
      QStringList failures;
      connect(&crashed->autosave(), &studio::Autosave::autosave_failed, this,
              [&](const QString& m) { failures << m; });
      studio::PrimitiveRequest request;
      request.center = core::Vec3(0.0, 0.07, 0.0);
      request.size = 0.01;
      request.cell_size = 0.005;
      QVERIFY(crashed->create_primitive(request));
      QVERIFY(autosaved.wait(10'000));
      unsaved = crashed->document().scenario();
      // The window goes away without closing (as in a crash): the copy stays.
      crashed.reset();
      QVERIFY2(failures.isEmpty(), qPrintable(failures.join('\n')));
    }
    QVERIFY(studio::Autosave::find_recovery(recovery).has_value());
    studio::MainWindow window(options("recovery-crash"));
    fs::path offered;
    QVERIFY(window.offer_recovery([&](const studio::RecoveryCopy& copy) {
      offered = copy.original_path;
      return true;
    }));
    QCOMPARE(offered, ball_package_);
    QVERIFY(window.document().scenario() == unsaved);
    QVERIFY(window.isWindowModified());
    QCOMPARE(window.document().path(), ball_package_);
    QVERIFY(window.save_as(dir() / "recovered.vscene"));
    window.autosave().wait();
    QVERIFY(!studio::Autosave::find_recovery(recovery).has_value());
  }

  void launchesTrainingAndShowsTheReport() {
    studio::MainWindow window(options());
    QVERIFY(window.open_package(ball_package_));
    QSignalSpy finished(&window, &studio::MainWindow::training_finished);
    QVERIFY(window.launch_training(0.1));
    QVERIFY(window.launcher().running());
    QVERIFY(finished.wait(300'000));
    const auto result = finished.takeFirst().at(0).value<studio::TrainingResult>();
    QCOMPARE(result.exit_code, 0);
    QVERIFY(!result.report.is_null());
    QCOMPARE(result.report.value("format", ""), std::string("viscera-session-report"));
    QVERIFY(result.report.value("simulated_time", 0.0) >= 0.099);
    QVERIFY(result.report.value("steps", 0) > 0);
    QVERIFY(window.report_text().startsWith("Simulated 0.1"));
    QVERIFY(window.report_text().contains("Ended:"));
  }

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

  void screenshotShowsTheTexturedScene() {
    studio::MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.open_package(textured_package_));
    QCOMPARE(window.scene_view()->textured_object_count(), 1);
    QSignalSpy finished(&window, &studio::MainWindow::training_finished);
    QVERIFY(window.launch_training(0.1));
    QVERIFY(finished.wait(120'000));
    studio::PrimitiveRequest pipe;
    pipe.kind = studio::PrimitiveKind::Pipe;
    pipe.center = core::Vec3(0.0, 0.0, -0.055);
    pipe.size = 0.008;
    pipe.length = 0.12;
    pipe.cell_size = 0.004;
    QVERIFY(window.create_primitive(pipe));
    window.scene_view()->show_scenario(window.document().scenario(), window.document().files(),
                                       true);
    window.select_object("ball");
    const fs::path phantom = dir() / "phantom.vti";
    write_phantom(phantom, {60, 60, 60}, 0.04);
    QVERIFY(window.open_image_volume(phantom));
    window.slice_views()->set_window_level(1200.0, 400.0);
    QTest::qWait(100);

    const QImage view = window.scene_view()->grabFramebuffer();
    QVERIFY(view.width() > 200 && view.height() > 200);
    const double tissue = tissue_share(view);
    QVERIFY2(tissue > 0.05, qPrintable(QString("tissue share %1").arg(tissue)));
    QVERIFY(grey_deviation(view) > 10.0);

    const QImage shot = window.grab().toImage();
    const QString path = QString::fromStdString((out_dir_ / "studio.png").string());
    QVERIFY(shot.save(path));
    const double shot_tissue = tissue_share(shot);
    QVERIFY2(shot_tissue > 0.015, qPrintable(QString("tissue share %1").arg(shot_tissue)));
    qInfo("screenshot: %s", qPrintable(path));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-tests"));
  MainWindowTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "main_window_test.moc"
