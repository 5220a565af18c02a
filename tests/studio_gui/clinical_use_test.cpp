// The studio as a clinician uses it (issue 23), driving the real main window under Xvfb: the
// template form fits a 768-px screen in clinical units; a clipping plane changes the picture; a
// polyp clicked on the outside of the uterus lands on the cavity wall, also after a bake, and an
// intramural myoma in the wall, its host re-meshed around it; the scene tree, the 3D view and
// the saved package agree after every command, undo, redo and reopen; the first layout and the
// empty material panel; the README's screenshot. The volume workflow is in
// volume_workflow_test.cpp.

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCamera.h>

#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QSettings>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTabBar>
#include <QTreeWidget>
#include <QtTest>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "studio/document/organ_authoring.h"
#include "studio/document/view_state.h"
#include "studio/ui/display_panel.h"
#include "studio/ui/main_window.h"
#include "studio/ui/material_panel.h"
#include "studio/ui/organ_panels.h"
#include "studio/ui/pathology_panel.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/template_dialog.h"
#include "studio/ui/texture_panel.h"
#include "templates/generator/simulation_check.h"
#include "templates/geometry/surface_queries.h"
#include "templates/template_catalog.h"
#include "templates/validation/patient_validation.h"
#include "tests/studio_gui/clinical_checks.h"
#include "tests/studio_gui/image_checks.h"
#include "tests/studio_gui/window_fixture.h"
#include "textures/scenario_baking.h"

namespace fs = std::filesystem;
using namespace viscera;
using namespace viscera::studio_tests;

class ClinicalUseTest : public QObject, public viscera::studio_tests::WindowFixture {
  Q_OBJECT

 private slots:
  void initTestCase() {
    make_folders();
    QElapsedTimer clock;
    clock.start();
    const core::Scenario patient = templates::build_from_template(
        "hysteroscopy", {{"vessel_terminals", "30"}, {"polyps", "1"}, {"submucosal_myomas", "1"}},
        3);
    patient_ = dir() / "patient.vscene";
    core::write_package(patient, patient_);
    qInfo("hysteroscopy patient built in %lld ms", static_cast<long long>(clock.elapsed()));
  }

  void templateFormFitsA768PixelScreenInClinicalUnits() {
    studio::TemplateDialog dialog;
    QVERIFY(dialog.select_template("hysteroscopy"));
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const QRect laptop(0, 0, 1366, 768);
    dialog.fit_to(laptop);
    QCoreApplication::processEvents();
    qInfo("dialog %d x %d (frame %d)", dialog.width(), dialog.height(),
          dialog.frameGeometry().height());
    QVERIFY(dialog.frameGeometry().height() <= 768);
    QVERIFY(dialog.width() <= 1366);
    // OK and Cancel lie inside the dialog; the parameters scroll instead.
    const QRect buttons(dialog.buttons()->mapTo(&dialog, QPoint(0, 0)), dialog.buttons()->size());
    QVERIFY(dialog.rect().contains(buttons));
    QVERIFY(dialog.parameter_area()->widget()->height() >
            dialog.parameter_area()->viewport()->height());

    // Clinical units and ranges: millimetres, degrees, kilopascals.
    QDoubleSpinBox* cervix = dialog.editor("cervix_length");
    QVERIFY(cervix != nullptr);
    QCOMPARE(cervix->suffix(), QString(" mm"));
    QCOMPARE(cervix->value(), 25.0);
    QCOMPARE(cervix->minimum(), 18.0);
    QCOMPARE(cervix->maximum(), 32.0);
    QDoubleSpinBox* flexion = dialog.editor("flexion");
    QCOMPARE(flexion->suffix(), QString(" °"));
    QVERIFY(std::abs(flexion->value() - 0.3 * 180.0 / M_PI) < 0.06);
    QCOMPARE(dialog.editor("myometrium_stiffness")->suffix(), QString(" kPa"));
    QVERIFY(dialog.overrides().empty());  // rounding the shown defaults changes nothing
    // Grouped, each field with a readable label.
    QStringList groups;
    for (const QGroupBox* box : dialog.findChildren<QGroupBox*>())
      groups << box->title();
    for (const char* title : {"Anatomy", "Pathologies", "Tissue", "Texture"})
      QVERIFY2(groups.contains(title), qPrintable(groups.join(", ")));
    QVERIFY(!dialog.findChildren<QLabel*>(QString(), Qt::FindChildrenRecursively).isEmpty());
    bool labelled = false;
    for (const QLabel* label : dialog.findChildren<QLabel*>())
      labelled = labelled || label->text() == "Cervix length";
    QVERIFY(labelled);
    // Values go back in SI for build_from_template.
    cervix->setValue(30.0);
    flexion->setValue(-10.0);
    const auto overrides = dialog.overrides();
    QCOMPARE(overrides.size(), std::size_t{2});
    QCOMPARE(overrides.at("cervix_length"), std::string("0.03"));
    QVERIFY(std::abs(std::stod(overrides.at("flexion")) + 10.0 * M_PI / 180.0) < 1e-9);
    QVERIFY(templates::resolve_parameters(templates::find_template("hysteroscopy"), overrides)
                .at("cervix_length") == 0.03);
  }

  void clippingPlaneChangesTheRenderedImage() {
    studio::MainWindow window(options());
    open_patient(window);
    studio::SceneView* view = window.scene_view();
    const auto grab = [view] {
      view->render();
      return view->grabFramebuffer();
    };
    const QImage whole = grab();
    studio::DisplayPanel* display = window.display_panel();
    display->set_clipping(true, 1, 0.5, false);
    QVERIFY(view->clipping());
    const QImage cut = grab();
    const double changed = changed_share(whole, cut);
    qInfo("clipping changed %.1f %% of the pixels", 100.0 * changed);
    QVERIFY(changed > 0.02);
    // Moving the plane moves the cut.
    display->clip_slider()->setValue(30);
    const QImage moved = grab();
    QVERIFY(changed_share(cut, moved) > 0.005);
    display->set_clipping(false);
    QVERIFY(changed_share(whole, grab()) < 0.001);

    // Opacity: the uterus at 30 % shows what lies behind and inside it.
    QVERIFY(window.set_object_opacity("uterus", 0.3));
    QCOMPARE(view->object_opacity("uterus"), 0.3);
    QVERIFY(changed_share(whole, grab()) > 0.02);

    // From the cervix into the cavity: the camera sits at the internal os.
    QVERIFY(display->view_from_cervix());
    const core::Landmark* os = nullptr;
    for (const auto& mark : window.document().scenario().landmarks)
      if (mark.id == "cervix-internal-os") os = &mark;
    QVERIFY(os != nullptr);
    const double* eye = view->renderer()->GetActiveCamera()->GetPosition();
    QVERIFY((core::Vec3(eye[0], eye[1], eye[2]) - os->position).norm() < 1e-9);
    QVERIFY(errors_.isEmpty());
  }

  void clickedPolypLandsOnTheCavitySideAlsoAfterABake() {
    studio::MainWindow window(options());
    open_patient(window);
    studio::SceneView* view = window.scene_view();
    // Bake the endometrium onto the uterus: its surface is cut at the atlas seams.
    window.select_object("uterus");
    studio::TextureRequest bake;
    bake.width = bake.height = 128;
    QVERIFY(window.organ_panels()->texture()->apply_texture(bake));
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
    const core::SceneObject* uterus = window.document().scenario().find_object("uterus");
    QVERIFY(uterus->surface.vertex_attributes.contains(textures::kSeamVertexAttribute));
    QVERIFY_EXCEPTION_THROWN(templates::SurfaceQueries baked(uterus->surface, "baked"),
                             core::InputError);

    // Click the middle of the view: the outside of the uterus.
    studio::PathologyPanel* panel = window.organ_panels()->pathologies();
    panel->set_choice("polyp", 0.006);
    panel->set_armed(true);
    const QPoint centre = view->rect().center();
    const auto hit = view->surface_point_at(centre);
    QVERIFY(hit.has_value());
    QCOMPARE(hit->first, QString("uterus"));
    const core::SurfaceMesh wall = textures::welded_surface(uterus->surface);
    const templates::SurfaceQueries tissue(wall, "uterus");
    QVERIFY(!on_cavity_side(wall, tissue, hit->second));  // the click is on the serosa
    const std::size_t before = window.document().scenario().pathologies.size();
    QTest::mouseClick(view, Qt::LeftButton, {}, centre);
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
    const core::Scenario& scenario = window.document().scenario();
    QCOMPARE(scenario.pathologies.size(), before + 1);
    const core::Pathology& polyp = scenario.pathologies.back();
    QCOMPARE(polyp.kind, std::string("polyp"));
    QVERIFY(on_cavity_side(wall, tissue, polyp.position));
    QVERIFY(tissue.closest(polyp.position).distance < 1e-3);
    // Its whole body hangs in the cavity: no vertex inside the wall, the centroid on the
    // cavity side.
    const core::SceneObject* object = scenario.find_object(polyp.object);
    QVERIFY(object != nullptr);
    core::Vec3 centroid = core::Vec3::Zero();
    for (const auto& v : object->surface.vertices) {
      QVERIFY(!tissue.inside(v) || tissue.closest(v).distance < 5e-4);
      centroid += v;
    }
    centroid /= static_cast<double>(object->surface.vertices.size());
    QVERIFY(on_cavity_side(wall, tissue, centroid));

    // A subserosal myoma clicked at the same place stays on the outside.
    panel->set_choice("myoma-subserosal", 0.008);
    QTest::mouseClick(view, Qt::LeftButton, {}, centre);
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
    const core::Pathology& myoma = window.document().scenario().pathologies.back();
    QCOMPARE(myoma.kind, std::string("myoma-subserosal"));
    QVERIFY(!on_cavity_side(wall, tissue, myoma.position));
  }

  void clickedIntramuralMyomaLiesInTheWallAndTheHostIsRemeshedAroundIt() {
    studio::MainWindow window(options());
    open_patient(window);
    studio::SceneView* view = window.scene_view();
    const core::Scenario before = window.document().scenario();
    const core::SceneObject& old_host = *before.find_object("uterus");
    const core::SurfaceMesh wall = textures::welded_surface(old_host.surface);
    const templates::SurfaceQueries tissue(wall, "uterus");

    // Click the outside of the uterus with an intramural myoma chosen (nothing selected: the
    // click selects the uterus, which fills the side panels and may resize the view).
    studio::PathologyPanel* panel = window.organ_panels()->pathologies();
    panel->set_choice("myoma-intramural", 0.006);
    panel->set_armed(true);
    const QPoint centre = view->rect().center();
    const auto hit = view->surface_point_at(centre);
    QVERIFY(hit.has_value());
    QCOMPARE(hit->first, QString("uterus"));
    QTest::mouseClick(view, Qt::LeftButton, {}, centre);
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
    const core::Scenario after = window.document().scenario();
    QCOMPARE(after.pathologies.size(), before.pathologies.size() + 1);
    const core::Pathology& myoma = after.pathologies.back();
    QCOMPARE(myoma.kind, std::string("myoma-intramural"));
    const core::SceneObject* sphere = after.find_object(myoma.object);
    QVERIFY(sphere != nullptr);
    QVERIFY(myoma.size >= 0.75 * 0.006 - 1e-12);
    // Inside the wall, with at least a millimetre of tissue all round.
    for (const auto& v : sphere->surface.vertices)
      QVERIFY(tissue.inside(v) && tissue.closest(v).distance > 1e-3);

    // The host is re-meshed around it: its tissue loses exactly the myoma's volume, keeps its
    // wall layers and its fixed cervix, and everything stays valid and simulates.
    const core::TetMesh& body = after.find_object("uterus")->body;
    const double removed = core::total_volume(old_host.body) - core::total_volume(body);
    const double myoma_volume = core::total_volume(sphere->body);
    qInfo("host %zu -> %zu tets; removed %.4g ml for a %.4g ml myoma", old_host.body.tets.size(),
          body.tets.size(), removed * 1e6, myoma_volume * 1e6);
    QVERIFY(std::abs(removed - myoma_volume) < 1e-6 * core::total_volume(old_host.body));
    const auto layer_volume = [](const core::TetMesh& mesh, int label) {
      double volume = 0.0;
      for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        if (mesh.tet_labels[t] == label) volume += core::signed_volume(mesh, static_cast<int>(t));
      return volume;
    };
    QCOMPARE(body.tet_labels.size(), body.tets.size());
    const double endometrium_before = layer_volume(old_host.body, 1);
    QVERIFY(std::abs(layer_volume(body, 1) - endometrium_before) < 0.1 * endometrium_before);
    double fixed_top = 0.0;
    for (std::size_t n = 0; n < old_host.body.nodes.size(); ++n)
      if (old_host.body.fixed[n]) fixed_top = std::max(fixed_top, old_host.body.nodes[n].z());
    int fixed = 0;
    for (std::size_t n = 0; n < body.nodes.size(); ++n) {
      if (!body.fixed[n]) continue;
      ++fixed;
      QVERIFY(body.nodes[n].z() <= fixed_top + 1e-3);
    }
    QVERIFY(fixed > 0);
    double mass_before = 0.0, mass_after = 0.0;
    for (const double m : old_host.body.node_mass)
      mass_before += m;
    for (const double m : body.node_mass)
      mass_after += m;
    QVERIFY(mass_after < mass_before);
    const templates::PatientValidation validation = templates::validate_patient_geometry(after);
    QVERIFY2(validation.valid(), validation.first_failure().c_str());
    // The simulated second of the generator's check, with the polyp left out: on its stalk it
    // swings past the check's bound in this patient, before the myoma as after it.
    const auto without_polyps = [](core::Scenario scenario) {
      for (const auto& pathology : scenario.pathologies) {
        if (pathology.kind != "polyp") continue;
        std::erase_if(scenario.objects, [&](const auto& o) { return o.id == pathology.object; });
        std::erase_if(scenario.connections, [&](const auto& c) {
          return c.object_a == pathology.object || c.object_b == pathology.object;
        });
      }
      std::erase_if(scenario.pathologies, [](const auto& p) { return p.kind == "polyp"; });
      return scenario;
    };
    QVERIFY(templates::simulate_one_second(without_polyps(before)).passed);
    const templates::ValidationCheck second = templates::simulate_one_second(without_polyps(after));
    QVERIFY2(second.passed, second.detail.c_str());
    QCOMPARE(second.measures.at("bodies").get<int>(), 3);

    // Undo puts the old body and connections back exactly; redo the new ones.
    QUndoStack* undo = window.document().undo_stack();
    undo->undo();
    QVERIFY(window.document().scenario() == before);
    undo->redo();
    QVERIFY(window.document().scenario() == after);
    QVERIFY(errors_.isEmpty());
  }

  void visibilityAgreesAfterEveryCommandUndoRedoAndReopen() {
    studio::MainWindow window(options());
    open_patient(window);
    QUndoStack* undo = window.document().undo_stack();
    const auto agree = [&window](const char* step) {
      const QString problem = disagreement(window);
      if (!problem.isEmpty()) qWarning("after %s: %s", step, qPrintable(problem));
      return problem.isEmpty();
    };
    QVERIFY(agree("opening"));
    QVERIFY(!window.document().scenario().vessel_trees.empty());
    // Ticks in the tree.
    window.scene_tree()->visibility_item("uterus")->setCheckState(0, Qt::Unchecked);
    QVERIFY(!window.scene_view()->object_visible("uterus"));
    QVERIFY(agree("hiding the uterus"));
    const QString vessels = QString::fromStdString(
        studio::vessel_tree_key(window.document().scenario().vessel_trees.front().id));
    window.scene_tree()->visibility_item(vessels)->setCheckState(0, Qt::Unchecked);
    QVERIFY(agree("hiding the vessels"));
    QVERIFY(window.set_object_opacity(
        QString::fromStdString(window.document().scenario().objects.back().id), 0.4));
    QVERIFY(agree("opacity"));
    // An editing command, then back and forth through the whole history.
    window.select_object("uterus");
    QVERIFY(!window.organ_panels()
                 ->pathologies()
                 ->place_pathology_at(core::Vec3(0.0, 0.0, 0.05), "polyp", 0.005)
                 .isEmpty());
    QVERIFY(agree("placing a polyp"));
    QVERIFY(window.document().is_dirty());
    const int steps = undo->count();
    QCOMPARE(steps, 4);
    for (int i = 0; i < steps; ++i) {
      undo->undo();
      QVERIFY(agree("undo"));
    }
    QVERIFY(window.scene_view()->object_visible("uterus"));
    for (int i = 0; i < steps; ++i) {
      undo->redo();
      QVERIFY(agree("redo"));
    }
    QVERIFY(!window.scene_view()->object_visible("uterus"));
    // Ticking a hidden box once shows it (not twice).
    window.scene_tree()->visibility_item("uterus")->setCheckState(0, Qt::Checked);
    QVERIFY(window.scene_view()->object_visible("uterus"));
    window.scene_tree()->visibility_item("uterus")->setCheckState(0, Qt::Unchecked);
    QVERIFY(agree("ticking twice"));

    // A group's box hides all its objects in one step; undo shows them again.
    QTreeWidgetItem* group = window.scene_tree()->visibility_item("uterus")->parent();
    QVERIFY(group != nullptr && group->childCount() >= 3);
    const int before_group = undo->count();
    window.scene_tree()->visibility_item("uterus")->setCheckState(0, Qt::Checked);
    QCOMPARE(group->checkState(0), Qt::Checked);
    group->setCheckState(0, Qt::Unchecked);
    QCOMPARE(undo->count(), before_group + 2);
    for (int c = 0; c < group->childCount(); ++c)
      QVERIFY(!window.scene_view()->object_visible(
          group->child(c)->data(0, studio::SceneTree::kVisibilityRole).toString()));
    QVERIFY(agree("hiding a group"));
    undo->undo();
    QCOMPARE(group->checkState(0), Qt::Checked);
    QVERIFY(agree("undoing the group"));
    window.scene_tree()->visibility_item("uterus")->setCheckState(0, Qt::Unchecked);
    QCOMPARE(group->checkState(0), Qt::PartiallyChecked);

    // Saved and reopened: the package holds the same view state.
    const studio::ViewState saved = studio::view_state_of(window.document().files());
    QVERIFY(saved.hidden.contains("uterus"));
    const fs::path path = dir() / "visibility.vscz";
    QVERIFY(window.save_as(path));
    QCOMPARE(studio::view_state_of(studio::read_document_content(path).files), saved);
    studio::MainWindow reopened(options());
    reopened.set_error_handler([this](const QString& m) { errors_ << m; });
    QVERIFY(reopened.open_package(path));
    QCOMPARE(studio::view_state_of(reopened.document().files()), saved);
    QVERIFY(!reopened.scene_view()->object_visible("uterus"));
    QVERIFY(disagreement(reopened).isEmpty());
    QVERIFY(errors_.isEmpty());
  }

  void firstLayoutEmptyPanelAndTabs() {
    QSettings().clear();
    studio::MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCoreApplication::processEvents();
    const int view_width = window.scene_view()->width();
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
      if (dock->isVisible() && !dock->isFloating() &&
          window.dockWidgetArea(dock) != Qt::BottomDockWidgetArea)
        QVERIFY2(dock->width() < view_width, qPrintable(dock->windowTitle()));
    }
    qInfo("3D view %d x %d in a %d x %d window", view_width, window.scene_view()->height(),
          window.width(), window.height());
    // Every tab's full title fits its tab.
    for (const QTabBar* bar : window.findChildren<QTabBar*>()) {
      for (int t = 0; t < bar->count(); ++t) {
        const QRect tab = bar->tabRect(t);
        const int length = std::max(tab.width(), tab.height());
        QVERIFY2(length >= bar->fontMetrics().horizontalAdvance(bar->tabText(t)),
                 qPrintable(bar->tabText(t)));
      }
    }
    // Nothing selected: no material, no numbers.
    QVERIFY(!window.material_panel()->editors_box()->isVisible());
    QVERIFY(!window.display_panel()->opacity_slider()->isEnabled());
    // The layout is remembered: the window's size and the docks' widths.
    window.resize(1100, 760);
    QCoreApplication::processEvents();
    QDockWidget* right = nullptr;
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
      if (right == nullptr && dock->isVisible() &&
          window.dockWidgetArea(dock) == Qt::RightDockWidgetArea)
        right = dock;
    }
    QVERIFY(right != nullptr);
    window.resizeDocks({right}, {340}, Qt::Horizontal);
    QCoreApplication::processEvents();
    const int right_width = right->width();
    window.close();
    studio::MainWindow again(options());
    QCOMPARE(again.size(), QSize(1100, 760));
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QCoreApplication::processEvents();
    QDockWidget* restored = again.findChild<QDockWidget*>(right->objectName());
    QVERIFY(restored != nullptr);
    qInfo("right dock %d px, restored %d px", right_width, restored->width());
    QVERIFY(std::abs(restored->width() - right_width) <= 2);
  }

  void screenshotOfTheClippedPatient() {
    QSettings().clear();  // the first layout
    studio::MainWindow window(options());
    open_patient(window);
    window.select_object("uterus");
    studio::TextureRequest bake;
    bake.width = bake.height = 256;
    QVERIFY(window.organ_panels()->texture()->apply_texture(bake));
    window.select_object("uterus");
    window.display_panel()->set_clipping(true, 1, 0.5, false);
    window.select_object({});
    window.scene_view()->renderer()->GetActiveCamera()->Dolly(1.15);
    window.scene_view()->renderer()->ResetCameraClippingRange();
    window.scene_view()->render();
    QTest::qWait(100);
    const QImage view = window.scene_view()->grabFramebuffer();
    QVERIFY(studio_tests::tissue_share(view) > 0.03);
    const QImage shot = window.grab().toImage();
    const QString path = QString::fromStdString((out_dir_ / "studio-hysteroscopy.png").string());
    QVERIFY(shot.save(path));
    qInfo("screenshot: %s", qPrintable(path));
    QVERIFY(errors_.isEmpty());
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-clinical-tests"));
  ClinicalUseTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "clinical_use_test.moc"
