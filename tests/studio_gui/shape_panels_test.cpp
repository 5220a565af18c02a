// Drives the shape panels of the real studio main window under Xvfb (issue 9 §4–5): a
// stress–strain CSV fitted and plotted, then applied to the organ's material; a model object's
// control point dragged with the mouse reshapes its surface; organ motility and a pulse applied
// as active deformations, and the motility preview moving the surface as the simulator's
// sim::OrganMotility does — each undone again.

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
#include <QtTest>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/materials/material_constants.h"
#include "core/modelling/model_document.h"
#include "simulator/physics/organ_motility.h"
#include "studio/document/model_objects.h"
#include "studio/ui/control_points.h"
#include "studio/ui/deformation_panel.h"
#include "studio/ui/main_window.h"
#include "studio/ui/material_fit_panel.h"
#include "studio/ui/organ_panels.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/stress_strain_plot.h"
#include "studio/ui/vessel_panel.h"
#include "tests/studio_gui/panel_test_base.h"

namespace fs = std::filesystem;
using namespace viscera;
using namespace viscera::studio_tests;

class ShapePanelsTest : public PanelTestBase {
  Q_OBJECT

 private slots:
  void initTestCase() { make_ball_package(); }

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
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-shape-panel-tests"));
  ShapePanelsTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "shape_panels_test.moc"
