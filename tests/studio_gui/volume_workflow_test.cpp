// The image-volume workflow as a clinician uses it (issue 23 §5), driving the real main window
// under Xvfb on CGAL's liver image: Mesh organ takes the label just grown and honours the tet
// count with a bar that moves; segmentation steps undo byte for byte; slice planes switch off,
// the volume and the document close; a label image renders coloured by label.

#include <QVTKOpenGLNativeWidget.h>
#include <vtkImageSlice.h>
#include <vtkPlane.h>

#include <QElapsedTimer>
#include <QProgressDialog>
#include <QSurfaceFormat>
#include <QTimer>
#include <QTreeWidget>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/image/downsample.h"
#include "core/image/image_volume_io.h"
#include "core/package/scenario_package.h"
#include "importers/volume/volume_reader.h"
#include "studio/ui/display_panel.h"
#include "studio/ui/main_window.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"
#include "studio/ui/segmentation_panel.h"
#include "studio/ui/slice_views.h"
#include "studio/ui/volume_rendering.h"
#include "templates/template_catalog.h"
#include "tests/studio_gui/image_checks.h"
#include "tests/studio_gui/liver_volume.h"
#include "tests/studio_gui/window_fixture.h"

namespace fs = std::filesystem;
using namespace viscera;

class VolumeWorkflowTest : public QObject, public viscera::studio_tests::WindowFixture {
  Q_OBJECT

 private:
  bool open_coarse_liver(studio::MainWindow& window) {
    const fs::path coarse = dir() / "liver_coarse.vti";
    if (!fs::exists(coarse)) {
      const fs::path liver = studio_tests::cgal_liver(dir());
      core::write_volume_vti(core::downsample(importers::read_volume(liver).volume, {4, 4, 2}),
                             coarse);
    }
    return window.open_image_volume(coarse);
  }

  /// Thresholds the coarse liver into label 1 and grows label 2 from deep inside it.
  void grow_liver_label_2(studio::MainWindow& window) {
    QVERIFY(open_coarse_liver(window));
    studio::SegmentationPanel* panel = window.segmentation_panel();
    QVERIFY(panel->segment_threshold(128.0, 255.0, 1));
    const core::ImageVolume& volume = panel->segmentation().volume();
    const std::array<int, 3> inside = studio_tests::deep_inside(volume, {54, 44, 41});
    QVERIFY(inside[0] >= 0);
    QVERIFY(panel->grow_region_at(
        volume.index_to_world(core::Vec3(inside[0], inside[1], inside[2])), 127.0, 2));
    QVERIFY(panel->segmentation().voxel_count(2) > 50'000);
  }

 private slots:
  void initTestCase() {
    make_folders();
    patient_ = dir() / "ball.vscene";
    core::write_package(templates::build_from_template("ball", {{"cell_size", "0.012"}}, 1),
                        patient_);
  }

  void meshOrganHonoursTheTetCountWithAMovingBar() {
    studio::MainWindow window(options());
    errors_.clear();
    window.set_error_handler([this](const QString& m) { errors_ << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    grow_liver_label_2(window);
    studio::SegmentationPanel* panel = window.segmentation_panel();
    // Mesh organ takes the label just grown.
    studio::OrganMeshRequest request = panel->mesh_request();
    QCOMPARE(request.label, std::uint16_t{2});
    request.target_tets = 5000;
    // Sample the bar while Mesh_3 runs.
    QList<int> values;
    QTimer sampler;
    connect(&sampler, &QTimer::timeout, &window, [&] {
      if (auto* dialog = window.findChild<QProgressDialog*>()) values << dialog->value();
    });
    sampler.start(20);
    QElapsedTimer clock;
    clock.start();
    const QString id = panel->mesh_segmentation(request);
    sampler.stop();
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join('\n')));
    QVERIFY(!id.isEmpty());
    const core::SceneObject* organ = window.document().scenario().find_object(id.toStdString());
    QVERIFY(organ != nullptr);
    const std::size_t tets = organ->body.tets.size();
    qInfo("5000 tets asked, %zu made in %lld ms; bar values sampled: %lld", tets,
          static_cast<long long>(clock.elapsed()), static_cast<long long>(values.size()));
    QVERIFY(tets >= 4000 && tets <= 6000);
    QList<int> distinct;
    for (int v : values)
      if (distinct.isEmpty() || distinct.back() != v) distinct << v;
    qInfo("distinct bar values: %lld", static_cast<long long>(distinct.size()));
    QVERIFY(distinct.size() >= 3);
    for (int i = 1; i < distinct.size(); ++i)
      QVERIFY(distinct[i] > distinct[i - 1]);  // it only moves forward
  }

  void segmentationUndoRestoresTheLabelsByteForByte() {
    studio::MainWindow window(options());
    errors_.clear();
    window.set_error_handler([this](const QString& m) { errors_ << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(open_coarse_liver(window));
    studio::SegmentationPanel* panel = window.segmentation_panel();
    const core::LabelMap empty = panel->segmentation().labels();
    QVERIFY(panel->segment_threshold(128.0, 255.0, 1));
    const core::LabelMap thresholded = panel->segmentation().labels();
    const core::ImageVolume& volume = panel->segmentation().volume();
    const std::array<int, 3> inside = studio_tests::deep_inside(volume, {54, 44, 41});
    QVERIFY(panel->grow_region_at(
        volume.index_to_world(core::Vec3(inside[0], inside[1], inside[2])), 127.0, 2));
    QVERIFY(panel->open_labels(1));
    const core::LabelMap opened = panel->segmentation().labels();
    QVERIFY(!(opened == thresholded));
    QCOMPARE(panel->history()->count(), 3);
    QVERIFY(panel->undo_step());
    QVERIFY(panel->undo_step());
    QVERIFY(panel->segmentation().labels().image.voxels == thresholded.image.voxels);
    QVERIFY(panel->undo_step());
    QVERIFY(panel->segmentation().labels().image.voxels == empty.image.voxels);
    QVERIFY(!panel->undo_step());
    QVERIFY(panel->redo_step() && panel->redo_step() && panel->redo_step());
    QVERIFY(panel->segmentation().labels().image.voxels == opened.image.voxels);
    // Segmentation steps are not document edits.
    QCOMPARE(window.document().undo_stack()->count(), 0);
    QVERIFY(errors_.isEmpty());
  }

  void slicePlanesVolumeAndDocumentClose() {
    studio::MainWindow window(options());
    open_patient(window);
    const fs::path phantom = dir() / "phantom.vti";
    studio_tests::write_phantom(phantom, {40, 40, 40}, 0.03);
    QVERIFY(window.open_image_volume(phantom));
    QVERIFY(window.has_image_volume());
    QVERIFY(window.slice_planes_shown());
    QCOMPARE(window.volume_rendering().preset(), std::string("CT soft tissue"));
    QTreeWidgetItem* box = window.scene_tree()->visibility_item(studio::SceneTree::kImageVolumeKey);
    QVERIFY(box != nullptr);
    box->setCheckState(0, Qt::Unchecked);
    QVERIFY(!window.slice_planes_shown());
    window.set_slice_planes_shown(true);
    QVERIFY(window.slice_planes_shown());
    // The clipping plane moves with the axial slice.
    studio::DisplayPanel* display = window.display_panel();
    display->set_follows_slices(true);
    display->set_clipping(true, 2, 0.5, false);
    studio::SliceViews* slices = window.slice_views();
    const core::ImageVolume& volume = window.segmentation_panel()->segmentation().volume();
    const auto slice_z = [&volume, slices] {
      return volume.index_to_world(core::Vec3(0.0, 0.0, slices->slice(2))).z();
    };
    std::vector<double> origins;
    for (const int k : {10, 30}) {
      slices->set_slice(2, k);
      QVERIFY(window.scene_view()->clipping());
      origins.push_back(window.scene_view()->clip_plane()->GetOrigin()[2]);
      QVERIFY(std::abs(origins.back() - slice_z()) < 1e-9);
      QCOMPARE(window.scene_view()->clip_plane()->GetNormal()[2], 1.0);
    }
    qInfo("clip plane z at slices 10 and 30: %.6f %.6f", origins[0], origins[1]);
    // 20 slices of 2 mm apart.
    QVERIFY(std::abs(origins[1] - origins[0] - 0.04) < 1e-6);
    display->set_clipping(false);
    window.close_image_volume();
    QVERIFY(!window.has_image_volume());
    QVERIFY(!window.slice_planes_shown());
    QVERIFY(window.scene_tree()->visibility_item(studio::SceneTree::kImageVolumeKey) == nullptr);
    QVERIFY(!window.segmentation_panel()->segmentation().has_volume());
    // A label image is rendered coloured by label.
    QVERIFY(open_coarse_liver(window));
    qInfo("coarse liver preset: %s", window.volume_rendering().preset().c_str());
    QVERIFY(window.close_document());
    QVERIFY(window.document().scenario().objects.empty());
    QVERIFY(!window.has_image_volume());
    QVERIFY(!window.document().is_dirty());
    QVERIFY(errors_.isEmpty());
  }

  void labelImageRendersColouredByLabel() {
    studio::MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const fs::path liver = studio_tests::cgal_liver(dir());
    core::ImageVolume labels = importers::read_volume(liver).volume;
    // Every 4th voxel along each axis keeps the 0/255 labels a label image has.
    core::ImageVolume small;
    small.dims = {labels.dims[0] / 4, labels.dims[1] / 4, labels.dims[2] / 2};
    small.spacing = labels.spacing.cwiseProduct(core::Vec3(4, 4, 2));
    small.origin = labels.origin;
    small.scalar_type = labels.scalar_type;
    small.allocate();
    const std::size_t bytes = core::scalar_size(labels.scalar_type);
    for (int k = 0; k < small.dims[2]; ++k)
      for (int j = 0; j < small.dims[1]; ++j)
        for (int i = 0; i < small.dims[0]; ++i)
          std::memcpy(&small.voxels[small.linear_index(i, j, k) * bytes],
                      &labels.voxels[labels.linear_index(4 * i, 4 * j, 2 * k) * bytes], bytes);
    const fs::path path = dir() / "liver_labels.vti";
    core::write_volume_vti(small, path);
    QVERIFY(window.open_image_volume(path));
    QCOMPARE(window.volume_rendering().preset(), std::string("Labels"));
    window.set_volume_rendering(true);
    window.set_slice_planes_shown(false);
    window.scene_view()->render();
    const QImage image = window.scene_view()->grabFramebuffer();
    // The liver in its label's colour, not an opaque box: saturated pixels on part of the view.
    QString values;
    for (const double v : window.volume_rendering().distinct_values())
      values += QString::number(v) + ' ';
    long coloured = 0;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); ++y) {
      for (int x = 0; x < rgb.width(); ++x) {
        const QRgb p = rgb.pixel(x, y);
        const int high = std::max({qRed(p), qGreen(p), qBlue(p)});
        const int low = std::min({qRed(p), qGreen(p), qBlue(p)});
        coloured += high - low > 80 ? 1 : 0;
      }
    }
    const double share = static_cast<double>(coloured) / (rgb.width() * rgb.height());
    qInfo("label rendering: %.1f %% coloured pixels (%s ray casting), label values %s",
          100.0 * share, window.volume_rendering().last_render_mode().c_str(), qPrintable(values));
    image.save(QString::fromStdString((out_dir_ / "label-rendering.png").string()));
    QVERIFY(share > 0.01 && share < 0.6);
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera-tests"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio-volume-workflow-tests"));
  VolumeWorkflowTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "volume_workflow_test.moc"
