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
#include "core/json_eigen.h"
#include "core/materials/shipped_materials.h"
#include "core/package/scenario_package.h"
#include "studio/ui/background_task.h"
#include "studio/ui/material_panel.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/slice_views.h"
#include "studio/ui/template_dialog.h"
#include "studio/ui/training_dialog.h"
#include "templates/template_catalog.h"
#include "tests/studio_gui/image_checks.h"
#include "textures/scenario_baking.h"

namespace fs = std::filesystem;
using namespace viscera;
using namespace viscera::studio_tests;

/// The slice views, Cancel and template dialog tests (views_test.cpp); returns failures.
int run_views_test(int argc, char** argv);

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

  void launchesAnInteractiveSessionDrivenByAScriptAndShowsItsReport() {
    studio::MainWindow window(options());
    QVERIFY(window.open_package(ball_package_));
    QStringList errors;
    window.set_error_handler([&](const QString& message) { errors << message; });
    // A script that moves the tool 5 mm sideways 10 cm above the ball, looking at it.
    core::Vec3 centre = core::Vec3::Zero();
    const auto& nodes = window.document().scenario().objects.front().body.nodes;
    for (const auto& node : nodes)
      centre += node / static_cast<double>(nodes.size());
    const core::Vec3 above = centre + core::Vec3(0.0, 0.0, 0.1);
    const nlohmann::json script = {
        {"format", "viscera-script"},
        {"version", 2},
        {"waypoints",
         {{{"t", 0.0}, {"tip", above}, {"look_at", centre}},
          {{"t", 0.4}, {"tip", above + core::Vec3(0.005, 0.0, 0.0)}, {"look_at", centre}}}}};
    const fs::path script_path = dir() / "interactive-script.json";
    std::ofstream(script_path) << script.dump();

    // The dialog's choice becomes the simulator's input.
    studio::TrainingDialog dialog(&window);
    studio::TrainingInput input;
    input.kind = studio::TrainingInput::Kind::Script;
    input.script = QString::fromStdString(script_path.string());
    dialog.set_input(input);
    dialog.set_duration(0.5);
    QCOMPARE(static_cast<int>(dialog.input().kind), static_cast<int>(input.kind));
    QCOMPARE(studio::input_arguments(dialog.input()),
             QStringList({QStringLiteral("--script"), input.script}));
    studio::TrainingInput device;
    device.kind = studio::TrainingInput::Kind::Device;
    device.port = 5123;
    QCOMPARE(studio::input_arguments(device),
             QStringList({QStringLiteral("--input"), QStringLiteral("udp:5123")}));

    QSignalSpy finished(&window, &studio::MainWindow::training_finished);
    QVERIFY(window.launch_interactive_training(dialog.input(), dialog.duration()));
    QVERIFY(window.launcher().running());
    QVERIFY(finished.wait(300'000));
    const auto result = finished.takeFirst().at(0).value<studio::TrainingResult>();
    QVERIFY2(result.exit_code == 0, qPrintable(result.output));
    QCOMPARE(result.report.value("format", ""), std::string("viscera-session-report"));
    // The session ran in the simulator's window, threaded in real time, not headless.
    QVERIFY(result.report["realtime"].is_object());
    QVERIFY(result.report["realtime"].value("frames", 0) > 0);
    QVERIFY(result.report.value("simulated_time", 0.0) >= 0.499);
    QVERIFY(window.report_text().startsWith("Simulated 0.5"));
    QVERIFY(window.report_text().contains("Ended:"));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join("; ")));

    // A script that is not there is refused in one sentence, nothing launched.
    input.script = QString::fromStdString((dir() / "missing.json").string());
    QVERIFY(!window.launch_interactive_training(input, 0.5));
    QCOMPARE(errors.size(), 1);
    QVERIFY(errors.front().contains("missing.json"));
    QVERIFY(!window.launcher().running());
  }

  void showsASimulationFailureInOneSentence() {
    studio::TrainingResult result;
    result.exit_code = static_cast<int>(core::ExitCode::SimulationFailed);
    result.output = QStringLiteral(
        "the haptic device drives the instrument\n"
        "viscera-sim: body \"ball\", node 12, step 40: the simulation became unstable at step 40 "
        "(t = 0.04 s): node 12 of body \"ball\" has a non-finite position; likely cause: "
        "non-finite state\n");
    const QString sentence = studio::failure_sentence(result);
    QVERIFY(sentence.startsWith("The simulation failed: body \"ball\", node 12, step 40"));
    QVERIFY(!sentence.contains('\n'));
    result.exit_code = 0;
    QVERIFY(studio::failure_sentence(result).isEmpty());
  }

  void screenshotShowsTheTexturedScene() {
    studio::MainWindow window(options());
    window.resize(1280, 800);  // the framing the shares below were measured at
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
    // The window holds more docks since issue 23 (Display), so the scene is a smaller share of
    // it than of the 3D view; still well above a blank or untextured window.
    QVERIFY2(shot_tissue > 0.01, qPrintable(QString("tissue share %1").arg(shot_tissue)));
    qInfo("screenshot: %s", qPrintable(path));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-tests"));
  MainWindowTest test;
  const int failed = QTest::qExec(&test, argc, argv);
  return failed + run_views_test(argc, argv);
}

#include "main_window_test.moc"
