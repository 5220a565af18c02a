// Drives the organ panels of the real studio main window under Xvfb (issue 9 §5): a texture
// applied to the selected organ shows its pixels in the 3D view; a CCO vessel tree grown in it
// has Murray-consistent radii for the chosen exponent; a polyp placed by clicking on the organ
// in the 3D view sits on its wall, and undo takes each back.

#include "studio/ui/organ_panels.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkHandleWidget.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <QDockWidget>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/materials/material_constants.h"
#include "core/modelling/model_document.h"
#include "core/package/scenario_package.h"
#include "simulator/physics/organ_motility.h"
#include "studio/document/model_objects.h"
#include "studio/ui/control_points.h"
#include "studio/ui/deformation_panel.h"
#include "studio/ui/main_window.h"
#include "studio/ui/material_fit_panel.h"
#include "studio/ui/pathology_panel.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/stress_strain_plot.h"
#include "studio/ui/texture_panel.h"
#include "studio/ui/vessel_panel.h"
#include "templates/geometry/surface_queries.h"
#include "templates/template_catalog.h"
#include "templates/vessels/vessel_tree_analysis.h"
#include "tests/studio_gui/image_checks.h"

namespace fs = std::filesystem;
using namespace viscera;
using namespace viscera::studio_tests;

namespace {

/// Mean |grey − its 5 × 5 box mean| over pixels whose whole box lies on tissue in `mask`
/// (red above blue by 30): fine detail on the organ, ≈ 0 for smooth shading.
double tissue_detail(const QImage& image, const QImage& mask) {
  const QImage grey = image.convertToFormat(QImage::Format_Grayscale8);
  const QImage m = mask.convertToFormat(QImage::Format_RGB32);
  const auto tissue = [&](int x, int y) {
    const QRgb p = m.pixel(x, y);
    return qRed(p) > qBlue(p) + 30;
  };
  double sum = 0.0;
  long count = 0;
  for (int y = 2; y + 2 < grey.height(); ++y) {
    for (int x = 2; x + 2 < grey.width(); ++x) {
      double box = 0.0;
      bool inside = true;
      for (int dy = -2; dy <= 2 && inside; ++dy) {
        for (int dx = -2; dx <= 2 && inside; ++dx) {
          inside = tissue(x + dx, y + dy);
          box += grey.constScanLine(y + dy)[x + dx];
        }
      }
      if (!inside) continue;
      sum += std::abs(grey.constScanLine(y)[x] - box / 25.0);
      ++count;
    }
  }
  return count == 0 ? 0.0 : sum / static_cast<double>(count);
}

}  // namespace

class OrganPanelsTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;
  fs::path ball_package_;

  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options() const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / "recovery";
    o.autosave_interval_ms = 600'000;
    return o;
  }

  /// A shown window with the ball open and selected; errors land in `errors`.
  void open_ball(studio::MainWindow& window, QStringList& errors) {
    window.set_error_handler([&errors](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.open_package(ball_package_));
    window.select_object("ball");
    QCOMPARE(window.organ_panels()->texture()->object_id(), QString("ball"));
  }

 private slots:
  void initTestCase() {
    QVERIFY(tmp_.isValid());
    const core::Scenario scenario =
        templates::build_from_template("ball", {{"cell_size", "0.012"}}, 1);
    ball_package_ = dir() / "ball.vscene";
    core::write_package(scenario, ball_package_);
  }

  void appliedTextureShowsInTheView() {
    QElapsedTimer clock;
    clock.start();
    studio::MainWindow window(options());
    QStringList errors;
    open_ball(window, errors);
    studio::SceneView* view = window.scene_view();
    QCOMPARE(view->textured_object_count(), 0);

    studio::TexturePanel* panel = window.organ_panels()->texture();
    panel->set_request({"endometrium", 3, 256, 256});
    panel->update_preview();
    QCOMPARE(panel->preview().size(), QSize(256, 256));
    QVERIFY(grey_deviation(panel->preview()) > 5.0);
    QVERIFY(panel->apply());
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));

    const core::Scenario& scenario = window.document().scenario();
    const core::SceneObject* ball = scenario.find_object("ball");
    QCOMPARE(ball->texture, std::string("ball-endometrium"));
    const core::TextureSpec& spec = scenario.textures.at("ball-endometrium");
    QCOMPARE(spec.seed, std::uint64_t{3});
    QVERIFY(!ball->surface.uvs.empty());
    QVERIFY(window.document().files().contains(spec.maps.at("albedo")));
    QCOMPARE(view->textured_object_count(), 1);
    QVERIFY(window.isWindowModified());

    // The same geometry from the same camera with and without (undo) the texture: the organ
    // shows texture detail only with it (no selection outline in either).
    window.select_object({});
    QTest::qWait(50);
    const QImage textured = view->grabFramebuffer();
    window.document().undo_stack()->undo();
    QTest::qWait(50);
    const QImage plain = view->grabFramebuffer();
    QCOMPARE(textured.size(), plain.size());
    QVERIFY(tissue_share(plain) > 0.05);
    window.document().undo_stack()->redo();
    const double before = tissue_detail(plain, plain);
    const double after = tissue_detail(textured, plain);
    qInfo("detail on the organ: %.2f grey levels before, %.2f after", before, after);
    QVERIFY2(after > 3.0 * before && after > 0.6,
             qPrintable(QString("%1 → %2").arg(before).arg(after)));

    window.document().undo_stack()->undo();
    QCOMPARE(view->textured_object_count(), 0);
    QVERIFY(window.document().scenario().find_object("ball")->texture.empty());
    QVERIFY(!window.document().scenario().textures.contains("ball-endometrium"));
    QVERIFY(window.document().files().empty());
    window.document().undo_stack()->redo();
    QCOMPARE(view->textured_object_count(), 1);
    QVERIFY(!window.isWindowModified() || window.document().is_dirty());
    qInfo("texture test: %lld ms", static_cast<long long>(clock.elapsed()));
  }

  void grownVesselsFollowMurraysLaw() {
    QElapsedTimer clock;
    clock.start();
    studio::MainWindow window(options());
    QStringList errors;
    open_ball(window, errors);
    studio::VesselPanel* panel = window.organ_panels()->vessels();
    studio::VesselRequest request;
    request.method = studio::VesselMethod::Cco;
    request.terminals = 40;
    request.murray_exponent = 2.7;
    request.seed = 5;
    panel->set_request(request);
    QVERIFY(panel->generate());
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));

    const auto& trees = window.document().scenario().vessel_trees;
    QCOMPARE(trees.size(), std::size_t{1});
    const core::VesselTree& tree = trees.front();
    QCOMPARE(tree.host_object, std::string("ball"));
    QCOMPARE(templates::terminal_count(tree), 40);
    const double deviation = templates::murray_deviation(tree, 2.7);
    QVERIFY2(deviation < 1e-6, qPrintable(QString::number(deviation)));
    // The exponent reached the generator: the same radii break the cubic law.
    QVERIFY(templates::murray_deviation(tree, 3.0) > 1e-3);
    for (const auto& segment : tree.segments)
      QVERIFY(segment.distal.norm() < 0.04 && segment.radius > 0.0);
    QCOMPARE(window.scene_view()->vessel_tree_count(), 1);
    const auto found = window.scene_tree()->findItems(QString::fromStdString(tree.id),
                                                      Qt::MatchExactly | Qt::MatchRecursive);
    QCOMPARE(found.size(), 1);

    window.document().undo_stack()->undo();
    QVERIFY(window.document().scenario().vessel_trees.empty());
    QCOMPARE(window.scene_view()->vessel_tree_count(), 0);
    qInfo("vessel test: %lld ms", static_cast<long long>(clock.elapsed()));
  }

  void clickPlacesAPolypOnTheWall() {
    QElapsedTimer clock;
    clock.start();
    studio::MainWindow window(options());
    QStringList errors;
    open_ball(window, errors);
    studio::SceneView* view = window.scene_view();
    studio::PathologyPanel* panel = window.organ_panels()->pathologies();
    panel->set_choice("polyp", 0.008);
    panel->set_armed(true);
    const QPoint centre = view->rect().center();
    const auto hit = view->surface_point_at(centre);
    QVERIFY(hit.has_value());
    QCOMPARE(hit->first, QString("ball"));
    const std::size_t objects = window.document().scenario().objects.size();
    const std::size_t connections = window.document().scenario().connections.size();

    QTest::mouseClick(view, Qt::LeftButton, {}, centre);
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
    const core::Scenario& scenario = window.document().scenario();
    QCOMPARE(scenario.pathologies.size(), std::size_t{1});
    const core::Pathology& polyp = scenario.pathologies.front();
    QCOMPARE(polyp.kind, std::string("polyp"));
    QCOMPARE(polyp.host_object, std::string("ball"));
    QCOMPARE(polyp.size, 0.008);
    QCOMPARE(scenario.objects.size(), objects + 1);
    const core::SceneObject* object = scenario.find_object(polyp.object);
    QVERIFY(object != nullptr);
    QCOMPARE(object->role, core::ObjectRole::Pathology);
    QVERIFY(object->body.tets.size() > 10);

    // On the wall where the click hit it.
    const templates::SurfaceQueries wall(scenario.find_object("ball")->surface, "ball");
    const double on_wall = wall.closest(polyp.position).distance;
    QVERIFY2(on_wall < 1e-3, qPrintable(QString("%1 m off the wall").arg(on_wall)));
    QVERIFY((polyp.position - hit->second).norm() < 1e-3);
    // The polyp stands outside the organ (no vertex in it) and is joined to it.
    for (const auto& v : object->surface.vertices)
      QVERIFY(!wall.inside(v) || wall.closest(v).distance < 1e-4);
    QCOMPARE(scenario.connections.size(), connections + 1);
    const core::Connection& joint = scenario.connections.back();
    QCOMPARE(joint.object_a, std::string("ball"));
    QCOMPARE(joint.object_b, polyp.object);
    QVERIFY(joint.node_pairs.size() >= 3);
    QVERIFY(window.scene_tree()->object_item(QString::fromStdString(polyp.object)) != nullptr);
    QVERIFY(view->object_visible(QString::fromStdString(polyp.object)));

    window.document().undo_stack()->undo();
    const core::Scenario& undone = window.document().scenario();
    QVERIFY(undone.pathologies.empty());
    QCOMPARE(undone.objects.size(), objects);
    QCOMPARE(undone.connections.size(), connections);
    QVERIFY(window.scene_tree()->object_item(QString::fromStdString("polyp")) == nullptr);

    // Disarmed, a click only selects.
    panel->set_armed(false);
    QTest::mouseClick(view, Qt::LeftButton, {}, centre);
    QVERIFY(window.document().scenario().pathologies.empty());
    qInfo("pathology test: %lld ms", static_cast<long long>(clock.elapsed()));
  }

  void fitsAMaterialFromACsv() {
    QElapsedTimer clock;
    clock.start();
    studio::MainWindow window(options());
    QStringList errors;
    open_ball(window, errors);
    // Samples of a known cubic, in kPa with a header, as a lab would export them.
    const std::array<double, 4> truth = {0.0, 2.0e4, 6.0e4, 1.5e5};
    const fs::path csv = dir() / "tissue.csv";
    {
      std::ofstream out(csv);
      out.precision(17);
      out << "# uniaxial tension\nstrain,stress_kpa\n";
      for (int i = 0; i <= 15; ++i) {
        const double e = 0.02 * i;
        out << e << "," << core::cubic_stress(truth, e) / 1000.0 << "\n";
      }
    }
    studio::MaterialFitPanel* panel = window.organ_panels()->material_fit();
    QVERIFY(panel->load_csv(csv));
    QCOMPARE(panel->samples().strain.size(), std::size_t{16});
    QVERIFY(panel->fit().has_value());
    for (int k = 1; k <= 3; ++k) {
      QVERIFY2(std::abs(panel->fit()->cubic[k] - truth[k]) < 1e-6 * truth[k],
               qPrintable(QString("c%1 = %2").arg(k).arg(panel->fit()->cubic[k])));
    }

    // The plot shows the samples and the curve in their colours; the last sample is on it.
    studio::StressStrainPlot* plot = panel->plot();
    plot->resize(320, 220);
    const QImage image = plot->grab().toImage().convertToFormat(QImage::Format_RGB32);
    int sample_pixels = 0, curve_pixels = 0;
    for (int y = 0; y < image.height(); ++y) {
      for (int x = 0; x < image.width(); ++x) {
        const QRgb p = image.pixel(x, y) | 0xff000000;
        sample_pixels += p == studio::StressStrainPlot::kSampleColour ? 1 : 0;
        curve_pixels += p == studio::StressStrainPlot::kCurveColour ? 1 : 0;
      }
    }
    QVERIFY2(
        sample_pixels > 16 * 5 && curve_pixels > 100,
        qPrintable(QString("%1 sample, %2 curve pixels").arg(sample_pixels).arg(curve_pixels)));
    const QPointF last = plot->to_pixel(0.3, core::cubic_stress(truth, 0.3));
    QVERIFY(QRectF(plot->rect()).contains(last));

    // Applied: the material carries the cubic and the Teschner constants derived from it.
    const std::string material_id = window.document().scenario().find_object("ball")->material;
    const core::Material before = window.document().scenario().materials.at(material_id);
    QVERIFY(panel->apply_fit());
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
    const core::Material& fitted = window.document().scenario().materials.at(material_id);
    QVERIFY(fitted.stress_strain.has_value());
    QCOMPARE(fitted.stress_strain->cubic.size(), std::size_t{4});
    QVERIFY(std::abs(fitted.stress_strain->cubic[2] - truth[2]) < 1e-6 * truth[2]);
    core::ElasticityOptions elasticity;
    elasticity.poisson_ratio = 0.45;
    const auto constants = core::teschner_constants(panel->fit()->cubic, 0.3, elasticity);
    QVERIFY(std::abs(fitted.distance_stiffness - constants.distance_stiffness) <
            1e-9 * constants.distance_stiffness);
    QCOMPARE(fitted.density, before.density);
    window.document().undo_stack()->undo();
    QVERIFY(window.document().scenario().materials.at(material_id) == before);

    // Editing a sample refits: the curve no longer passes through every sample.
    panel->edit_sample(5, 1, core::cubic_stress(truth, 0.1) + 2000.0);
    QVERIFY(panel->fit().has_value());
    QVERIFY(panel->fit()->rms_error > 100.0);
    QVERIFY(std::abs(panel->fit()->cubic[1] - truth[1]) > 1.0);
    qInfo("material test: %lld ms", static_cast<long long>(clock.elapsed()));
  }

  void draggingAControlPointReshapesTheSurface() {
    QElapsedTimer clock;
    clock.start();
    studio::MainWindow window(options());
    QStringList errors;
    open_ball(window, errors);
    // A 4 × 4 open sheet above the ball, facing the camera's side.
    core::ModelDocument sheet;
    sheet.id = "sheet";
    sheet.name = "Sheet";
    sheet.kind = core::ModelKind::Flat;
    sheet.flat = core::make_flat(core::Vec3(-0.03, -0.03, 0.06), core::Vec3(0.06, 0.0, 0.0),
                                 core::Vec3(0.0, 0.06, 0.0), 4, 4);
    sheet.flat.open = true;
    studio::ControlPointPanel* panel = window.organ_panels()->control_points();
    QCOMPARE(panel->add_model(sheet), QString("sheet"));
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
    QCOMPARE(window.scene_view()->selected_object(), QString("sheet"));
    QCOMPARE(panel->handle_count(), 16);
    window.scene_view()->reset_camera();
    window.scene_view()->render();
    QTest::qWait(50);
    const core::SurfaceMesh before = window.document().scenario().find_object("sheet")->surface;
    const std::string model_before = window.document().files().at(studio::model_file_path("sheet"));

    // Drag control point 5 (row 1, column 1) 40 pixels up on the screen with the mouse.
    const int index = 5;
    const core::Vec3 start = panel->handle_position(index);
    QVERIFY((start - sheet.flat.control_points[index]).norm() < 1e-12);
    studio::SceneView* view = window.scene_view();
    vtkRenderer* renderer = view->renderer();
    renderer->SetWorldPoint(start.x(), start.y(), start.z(), 1.0);
    renderer->WorldToDisplay();
    const double* display = renderer->GetDisplayPoint();
    const double ratio = view->devicePixelRatioF();
    const QPoint from(static_cast<int>(std::lround(display[0] / ratio)),
                      static_cast<int>(std::lround(view->height() - 1 - display[1] / ratio)));
    const auto send = [&](QEvent::Type type, QPoint at, Qt::MouseButtons buttons) {
      QMouseEvent event(type, at, view->mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
      QApplication::sendEvent(view, &event);
    };
    const int undo_steps = window.document().undo_stack()->count();
    send(QEvent::MouseButtonPress, from, Qt::LeftButton);
    for (int step = 1; step <= 4; ++step)
      send(QEvent::MouseMove, from - QPoint(0, 10 * step), Qt::LeftButton);
    send(QEvent::MouseButtonRelease, from - QPoint(0, 40), Qt::NoButton);
    QTRY_COMPARE_WITH_TIMEOUT(window.document().undo_stack()->count(), undo_steps + 1, 5000);
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));

    // The model's point moved with the mouse, the surface with it; the handles follow.
    const auto moved = studio::object_model(window.document().files(), "sheet");
    QVERIFY(moved.has_value());
    const core::Vec3 to = core::model_control_points(*moved)[index];
    qInfo("point %d moved by %.2f mm", index, 1000.0 * (to - start).norm());
    QVERIFY((to - start).norm() > 0.002);
    QVERIFY((to - panel->handle_position(index)).norm() < 1e-9);
    const core::SurfaceMesh& after = window.document().scenario().find_object("sheet")->surface;
    QCOMPARE(after.vertices.size(), before.vertices.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < after.vertices.size(); ++i)
      largest = std::max(largest, (after.vertices[i] - before.vertices[i]).norm());
    QVERIFY2(largest > 0.5 * (to - start).norm(), qPrintable(QString::number(largest)));

    window.document().undo_stack()->undo();
    QVERIFY(window.document().scenario().find_object("sheet")->surface == before);
    QCOMPARE(window.document().files().at(studio::model_file_path("sheet")), model_before);
    QVERIFY((panel->handle_position(index) - start).norm() < 1e-12);

    // The model travels with the package.
    const fs::path saved = dir() / "sheet.vscene";
    QVERIFY(window.save_as(saved));
    const studio::DocumentContent reopened = studio::read_document_content(saved);
    QCOMPARE(reopened.files.at(studio::model_file_path("sheet")), model_before);
    qInfo("control point test: %lld ms", static_cast<long long>(clock.elapsed()));
  }

  void motilityIsAppliedAndPreviewedBySimulatorMotion() {
    QElapsedTimer clock;
    clock.start();
    studio::MainWindow window(options());
    QStringList errors;
    open_ball(window, errors);
    studio::DeformationPanel* panel = window.organ_panels()->deformation();
    core::MotilitySpec spec;
    spec.amplitude_mean = 0.003;
    spec.wave_speed = 0.02;
    spec.wave_direction = core::Vec3(0.0, 0.0, 1.0);
    spec.frequency = 1.0;
    spec.frequency_disturbance = 0.1;
    spec.contraction_interval_mean = 2.0;
    panel->set_motility(spec);
    QVERIFY(panel->motility() == spec);
    QVERIFY(panel->apply_motility());
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
    const auto& deformations = window.document().scenario().active_deformations;
    QCOMPARE(deformations.size(), std::size_t{1});
    QCOMPARE(deformations.front().id, std::string("ball-motility"));
    QCOMPARE(deformations.front().target_object, std::string("ball"));
    QVERIFY(std::get<core::MotilitySpec>(deformations.front().spec) == spec);
    window.document().undo_stack()->undo();
    QVERIFY(window.document().scenario().active_deformations.empty());
    window.document().undo_stack()->redo();

    // A pulse on a tree grown in the ball; a pulse the seed's checks refuse is not added.
    studio::VesselRequest vessels;
    vessels.terminals = 12;
    QVERIFY(window.organ_panels()->vessels()->generate_vessels(vessels));
    const QString tree = QString::fromStdString(window.document().scenario().vessel_trees[0].id);
    QVERIFY(panel->apply_pulse(tree, 72.0, 6.0, 0.04));
    const auto& pulse = window.document().scenario().active_deformations.back();
    QCOMPARE(pulse.id, tree.toStdString() + "-pulse");
    QCOMPARE(std::get<core::PulseSpec>(pulse.spec).heart_rate, 72.0);
    QCOMPARE(std::get<core::PulseSpec>(pulse.spec).vessel_tree, tree.toStdString());
    QVERIFY(!panel->apply_pulse(tree, -5.0, 6.0, 0.04));
    QVERIFY(!panel->apply_pulse("no-such-tree", 72.0, 6.0, 0.04));
    QCOMPARE(errors.size(), 2);
    errors.clear();
    QCOMPARE(window.document().scenario().active_deformations.size(), std::size_t{2});

    // The preview moves the drawn surface exactly as sim::OrganMotility moves the knots.
    auto* dock = window.findChild<QDockWidget*>("DeformationPanel-dock");
    QVERIFY(dock != nullptr);
    dock->raise();
    QTest::qWait(20);
    QVERIFY(panel->isVisible());
    QVERIFY(panel->start_preview());
    QVERIFY(panel->previewing());
    const auto& rest = window.document().scenario().find_object("ball")->surface.vertices;
    const sim::OrganMotility motion(spec, rest, studio::DeformationPanel::kPreviewSeed);
    panel->preview_at(0.37);
    auto* polydata = vtkPolyData::SafeDownCast(
        window.scene_view()->object_actor("ball")->GetMapper()->GetInputDataObject(0, 0));
    QCOMPARE(polydata->GetNumberOfPoints(), static_cast<vtkIdType>(rest.size()));
    const auto expected = motion.positions(0.37);
    double largest_error = 0.0, largest_motion = 0.0;
    for (std::size_t i = 0; i < rest.size(); ++i) {
      double p[3];
      polydata->GetPoint(static_cast<vtkIdType>(i), p);
      const core::Vec3 drawn(p[0], p[1], p[2]);
      largest_error = std::max(largest_error, (drawn - expected[i]).norm());
      largest_motion = std::max(largest_motion, (drawn - rest[i]).norm());
    }
    QVERIFY2(largest_error < 1e-6, qPrintable(QString::number(largest_error)));
    QVERIFY2(largest_motion > 0.002, qPrintable(QString::number(largest_motion)));
    // The timer animates it; closing the panel stops it and puts the surface back.
    QTest::qWait(120);
    QVERIFY(panel->previewing());
    dock->close();
    QVERIFY(!panel->previewing());
    polydata = vtkPolyData::SafeDownCast(
        window.scene_view()->object_actor("ball")->GetMapper()->GetInputDataObject(0, 0));
    for (std::size_t i = 0; i < rest.size(); i += 7) {
      double p[3];
      polydata->GetPoint(static_cast<vtkIdType>(i), p);
      QVERIFY((core::Vec3(p[0], p[1], p[2]) - rest[i]).norm() < 1e-6);
    }
    qInfo("motility test: %lld ms", static_cast<long long>(clock.elapsed()));
  }

  void placementRefusesWithoutRoomOrObject() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&errors](const QString& m) { errors << m; });
    studio::PathologyPanel* panel = window.organ_panels()->pathologies();
    QVERIFY(panel->place_pathology_at(core::Vec3(0.0, 0.0, 0.04), "polyp", 0.008).isEmpty());
    QCOMPARE(errors.size(), 1);
    QVERIFY(window.open_package(ball_package_));
    window.select_object("ball");
    QVERIFY(panel->place_pathology_at(core::Vec3(0.0, 0.0, 0.04), "adhesion", 0.008).isEmpty());
    QCOMPARE(errors.size(), 2);
    QVERIFY(errors.back().contains("adhesion"));
    QVERIFY(window.document().scenario().pathologies.empty());
    QVERIFY(!window.document().is_dirty());
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-organ-tests"));
  OrganPanelsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "organ_panels_test.moc"
