// Segmentation in the studio (issue 9 §4) on a real volume, in the real main window under Xvfb:
// CGAL's liver image (libcgal-demo), downsampled, thresholded, grown from a point clicked in the
// axial slice view, meshed into an organ object; undo/redo, Cancel and errors.
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QProgressDialog>
#include <QPushButton>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>
#include <cstdlib>
#include <filesystem>

#include "core/image/downsample.h"
#include "core/image/image_volume_io.h"
#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "core/segmentation/region_growing.h"
#include "importers/volume/volume_reader.h"
#include "studio/ui/label_overlay.h"
#include "studio/ui/main_window.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/segmentation_panel.h"
#include "studio/ui/slice_views.h"
#include "studio/ui/volume_rendering.h"
#include "tests/studio_gui/image_checks.h"

namespace fs = std::filesystem;
using namespace viscera;

class SegmentationTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir tmp_;

  fs::path dir() const { return fs::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options() const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / "recovery";
    return o;
  }

  /// CGAL's liver.inr.gz (438 × 353 × 165 voxels of 0.617 × 0.617 × 1.333 mm; 255 in the
  /// liver, 0 outside), extracted from libcgal-demo's data archive.
  fs::path liver() const {
    const fs::path path = dir() / "data/images/liver.inr.gz";
    if (!fs::exists(path)) {
      const std::string command = "tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C '" +
                                  dir().string() + "' data/images/liver.inr.gz";
      if (std::system(command.c_str()) != 0) qWarning("%s failed", command.c_str());
    }
    return path;
  }

  /// The window with the liver opened and downsampled ×4 in-plane, ×2 across slices
  /// (109 × 88 × 82 voxels of about 2.5 mm).
  bool open_liver(studio::MainWindow& window) {
    return window.open_image_volume(liver()) && window.downsample_image_volume({4, 4, 2});
  }

  /// The same downsampled liver, saved once as .vti by the library functions the window calls
  /// (reading the full 25 M voxels for every test would dominate the suite's time).
  bool open_coarse_liver(studio::MainWindow& window) {
    const fs::path coarse = dir() / "liver_coarse.vti";
    if (!fs::exists(coarse)) {
      core::write_volume_vti(core::downsample(importers::read_volume(liver()).volume, {4, 4, 2}),
                             coarse);
    }
    return window.open_image_volume(coarse);
  }

  /// The voxel of the axial slice `near`[2] nearest `near` whose 5 × 5 × 3 neighbourhood holds
  /// 255 only; (-1, -1, -1) when there is none.
  static std::array<int, 3> deep_inside(const core::ImageVolume& v, std::array<int, 3> near) {
    std::array<int, 3> best{-1, -1, -1};
    int best_distance = 1 << 30;
    const int k = near[2];
    for (int j = 2; j < v.dims[1] - 2; ++j)
      for (int i = 2; i < v.dims[0] - 2; ++i) {
        bool all = true;
        for (int c = -1; c <= 1 && all; ++c)
          for (int b = -2; b <= 2 && all; ++b)
            for (int a = -2; a <= 2 && all; ++a)
              all = v.value(v.linear_index(i + a, j + b, k + c)) == 255.0;
        const int distance = (i - near[0]) * (i - near[0]) + (j - near[1]) * (j - near[1]);
        if (all && distance < best_distance) {
          best = {i, j, k};
          best_distance = distance;
        }
      }
    return best;
  }

 private slots:
  void thresholdGrowFromAClickAndMeshAnOrgan() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(open_liver(window));
    studio::SegmentationPanel* panel = window.segmentation_panel();
    const auto& segmentation = panel->segmentation();
    QCOMPARE(segmentation.volume().dims, (std::array<int, 3>{109, 88, 82}));

    QVERIFY(panel->segment_threshold(128.0, 255.0, 1));
    const std::size_t thresholded = segmentation.voxel_count(1);
    QVERIFY(thresholded > 50'000);

    // Click the axial view where a voxel deep inside the liver is drawn: the one nearest voxel
    // (54, 44, 41) — voxel (219, 176, 82) of the full image — whose 5 × 5 × 3 neighbourhood is
    // all liver (255).
    const core::ImageVolume& volume = segmentation.volume();
    const std::array<int, 3> inside = deep_inside(volume, {54, 44, 41});
    QVERIFY(inside[0] >= 0);
    studio::SliceViews* slices = window.slice_views();
    slices->set_slice(2, inside[2]);
    const core::Vec3 target = volume.index_to_world(core::Vec3(inside[0], inside[1], inside[2]));
    const QPoint pixel = slices->position_of(2, target);
    QVERIFY(slices->view(2)->rect().contains(pixel));
    QTest::mouseClick(slices->view(2), Qt::LeftButton, Qt::NoModifier, pixel);
    QVERIFY(panel->seed().has_value());
    // The seed lies on the axial slice, within a voxel of the target in-plane.
    QVERIFY(std::abs((*panel->seed() - target).z()) < 1e-9);
    QVERIFY((*panel->seed() - target).norm() < volume.spacing.x());
    const auto seed_voxel = core::voxel_at(volume, *panel->seed());
    QCOMPARE(seed_voxel[2], inside[2]);

    // Grow label 2 from the seed (255) within 127: the thresholded voxels connected to the
    // seed; then clean up as `viscera segment --open 1 --largest` does.
    const double seed_value =
        volume.value(volume.linear_index(seed_voxel[0], seed_voxel[1], seed_voxel[2]));
    QCOMPARE(seed_value, 255.0);
    QVERIFY(panel->grow_region_at(*panel->seed(), 127.0, 2));
    const std::size_t grown = segmentation.voxel_count(2);
    qInfo("seed voxel %d %d %d value %g: %zu of %zu voxels grown", seed_voxel[0], seed_voxel[1],
          seed_voxel[2], seed_value, grown, thresholded);
    QVERIFY(grown > 50'000);
    QVERIFY(grown <= thresholded);
    QCOMPARE(segmentation.voxel_count(1) + grown, thresholded);
    QVERIFY(panel->open_labels(1));
    QVERIFY(panel->keep_largest());
    const std::size_t kept = segmentation.voxel_count(2);
    QVERIFY(kept > 0.9 * grown && kept <= grown);

    // Mesh label 2 into an organ object: one undo step; its tets fill the label's volume.
    QUndoStack* undo = window.document().undo_stack();
    const int steps = undo->count();
    studio::OrganMeshRequest request;
    request.label = 2;
    request.name = "Liver";
    request.target_tets = 3000;
    request.triangles = 3000;
    const QString id = panel->mesh_segmentation(request);
    QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
    QCOMPARE(id, QString("liver"));
    QCOMPARE(undo->count(), steps + 1);
    const core::SceneObject* organ = window.document().scenario().find_object("liver");
    QVERIFY(organ != nullptr);
    QCOMPARE(organ->body_kind, core::BodyKind::TetMesh);
    QCOMPARE(organ->material, std::string("liver"));
    QVERIFY(window.document().scenario().materials.contains("liver"));
    QCOMPARE(organ->body.node_mass.size(), organ->body.nodes.size());
    QCOMPARE(organ->embedding.tet.size(), organ->surface.vertices.size());
    const double voxel_volume = segmentation.label_volume(2);
    const double tet_volume = core::total_volume(organ->body);
    const double surface_volume = core::enclosed_volume(organ->surface);
    qInfo("label %.1f ml, tets %.1f ml, surface %.1f ml, %zu tets", voxel_volume * 1e6,
          tet_volume * 1e6, surface_volume * 1e6, organ->body.tets.size());
    QVERIFY(std::abs(tet_volume / voxel_volume - 1.0) < 0.04);
    QVERIFY(std::abs(surface_volume / voxel_volume - 1.0) < 0.04);
    QCOMPARE(window.scene_view()->selected_object(), QString("liver"));

    undo->undo();
    QVERIFY(window.document().scenario().find_object("liver") == nullptr);
    undo->redo();
    const core::SceneObject* again = window.document().scenario().find_object("liver");
    QVERIFY(again != nullptr);
    QCOMPARE(again->body.tets.size(), organ->body.tets.size());

    // A label without voxels: one line in the error dialog, the document as it was.
    const std::size_t objects = window.document().scenario().objects.size();
    request.label = 7;
    QVERIFY(panel->mesh_segmentation(request).isEmpty());
    QCOMPARE(errors.size(), 1);
    QVERIFY(!errors[0].contains('\n'));
    QVERIFY(errors[0].contains("label 7"));
    QCOMPARE(window.document().scenario().objects.size(), objects);
    QCOMPARE(undo->count(), steps + 1);
  }

  void volumeRenderingPresetsAndLabelOverlay() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(!window.set_volume_preset("CT bone"));  // no volume yet: an error, nothing shown
    QCOMPARE(errors.size(), 1);
    QVERIFY(open_coarse_liver(window));
    QCOMPARE(window.segmentation_panel()->segmentation().volume().dims,
             (std::array<int, 3>{109, 88, 82}));
    studio::SceneView* view = window.scene_view();
    const auto grab = [view] {
      view->render();
      return view->grabFramebuffer();
    };
    // The slice planes alone are grey: no warm pixels.
    QVERIFY(!window.volume_rendering_shown());
    const double planes_only = studio_tests::tissue_share(grab());
    QVERIFY(planes_only < 0.002);
    std::vector<double> shares;
    std::vector<QImage> images;
    for (const auto& preset : studio::volume_presets()) {
      QVERIFY(window.set_volume_preset(QString::fromStdString(preset.name)));
      QVERIFY(window.volume_rendering_shown());
      QCOMPARE(window.volume_rendering().preset(), preset.name);
      images.push_back(grab());
      shares.push_back(studio_tests::tissue_share(images.back()));
      qInfo("%s: %.1f %% warm pixels (%s ray casting)", preset.name.c_str(), 100.0 * shares.back(),
            window.volume_rendering().last_render_mode().c_str());
      QVERIFY(window.volume_rendering().last_render_mode() != "none");
      QVERIFY(shares.back() > 0.01);  // the liver (255) is drawn in the preset's colours
    }
    QVERIFY(images[0] != images[1] && images[1] != images[2]);
    QVERIFY(!window.set_volume_preset("CT lung"));
    QCOMPARE(errors.size(), 2);
    window.set_volume_rendering(false);
    QVERIFY(studio_tests::tissue_share(grab()) < 0.002);

    // The label overlay: the thresholded liver in label 1's red over the grey axial slice.
    studio::SliceViews* slices = window.slice_views();
    slices->set_slice(2, 41);
    QVERIFY(studio_tests::tissue_share(slices->grab_view(2)) < 0.002);
    QVERIFY(window.segmentation_panel()->segment_threshold(128.0, 255.0, 1));
    const double red = studio_tests::tissue_share(slices->grab_view(2));
    qInfo("overlay: %.1f %% red pixels in the axial view", 100.0 * red);
    QVERIFY(red > 0.02);
    window.label_overlay()->set_opacity(0.0);
    QVERIFY(studio_tests::tissue_share(slices->grab_view(2)) < 0.002);
    window.label_overlay()->set_opacity(0.5);
    // A slice below the liver has no labels.
    slices->set_slice(2, 0);
    QVERIFY(studio_tests::tissue_share(slices->grab_view(2)) < 0.002);
    // Label files on another grid are refused, the labels kept.
    const fs::path other = dir() / "other.vti";
    studio_tests::write_phantom(other, {8, 8, 8}, 0.004);
    const std::size_t labelled = window.segmentation_panel()->segmentation().voxel_count(1);
    QVERIFY(!window.segmentation_panel()->load_label_map(other));
    QCOMPARE(errors.size(), 3);
    QCOMPARE(window.segmentation_panel()->segmentation().voxel_count(1), labelled);
    // A label file on the volume's grid replaces the labels (as `viscera segment` writes them).
    const fs::path saved = dir() / "liver_labels.vti";
    core::LabelMap relabelled = window.segmentation_panel()->segmentation().labels();
    for (std::size_t v = 0; v < relabelled.image.voxel_count(); ++v)
      if (relabelled.label(v) == 1) relabelled.set_label(v, 3);
    core::write_label_map_vti(relabelled, saved);
    QVERIFY(window.segmentation_panel()->load_label_map(saved));
    QCOMPARE(window.segmentation_panel()->segmentation().voxel_count(1), std::size_t{0});
    QCOMPARE(window.segmentation_panel()->segmentation().voxel_count(3), labelled);
  }

  void cancelWhileMeshingLeavesTheDocumentUnchanged() {
    studio::MainWindow window(options());
    QStringList errors;
    window.set_error_handler([&](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(open_coarse_liver(window));
    studio::SegmentationPanel* panel = window.segmentation_panel();
    QVERIFY(panel->segment_threshold(128.0, 255.0, 1));
    const bool dirty = window.document().is_dirty();
    QTimer::singleShot(700, &window, [&window] {
      auto* dialog = window.findChild<QProgressDialog*>();
      auto* button = dialog != nullptr ? dialog->findChild<QPushButton*>() : nullptr;
      if (button != nullptr) button->click();
    });
    studio::OrganMeshRequest request;
    request.target_tets = 200'000;  // far longer than the 0.7 s before Cancel
    QVERIFY(panel->mesh_segmentation(request).isEmpty());
    QVERIFY(errors.isEmpty());
    QVERIFY(window.document().scenario().objects.empty());
    QCOMPARE(window.document().undo_stack()->count(), 0);
    QCOMPARE(window.document().is_dirty(), dirty);
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-segmentation-tests"));
  SegmentationTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "segmentation_test.moc"
