// Drives the organ panels of the real studio main window under Xvfb (issue 9 §5): a texture
// applied to the selected organ shows its pixels in the 3D view; a CCO vessel tree grown in it
// has Murray-consistent radii for the chosen exponent; a polyp placed by clicking on the organ
// in the 3D view sits on its wall, and undo takes each back.

#include "studio/ui/organ_panels.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QElapsedTimer>
#include <QSurfaceFormat>
#include <QTreeWidget>
#include <QtTest>
#include <cmath>
#include <filesystem>

#include "studio/ui/main_window.h"
#include "studio/ui/pathology_panel.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/texture_panel.h"
#include "studio/ui/vessel_panel.h"
#include "templates/geometry/surface_queries.h"
#include "templates/vessels/vessel_tree_analysis.h"
#include "tests/studio_gui/image_checks.h"
#include "tests/studio_gui/panel_test_base.h"

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

class OrganPanelsTest : public PanelTestBase {
  Q_OBJECT

 private slots:
  void initTestCase() { make_ball_package(); }

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
