#include "tests/studio_gui/clinical_checks.h"

#include <QTreeWidgetItem>
#include <cmath>
#include <cstdlib>

#include "studio/document/view_state.h"
#include "studio/ui/scene_tree.h"
#include "studio/ui/scene_view.h"

namespace viscera::studio_tests {

double changed_share(const QImage& a, const QImage& b) {
  const QImage x = a.convertToFormat(QImage::Format_Grayscale8);
  const QImage y = b.convertToFormat(QImage::Format_Grayscale8);
  if (x.size() != y.size()) return 1.0;
  long changed = 0;
  for (int r = 0; r < x.height(); ++r)
    for (int c = 0; c < x.width(); ++c)
      changed += std::abs(x.constScanLine(r)[c] - y.constScanLine(r)[c]) > 24 ? 1 : 0;
  return static_cast<double>(changed) / (x.width() * x.height());
}

bool on_cavity_side(const core::SurfaceMesh& wall, const templates::SurfaceQueries& queries,
                    const core::Vec3& p) {
  const templates::SurfacePoint near = queries.closest(p);
  const auto& cavity = wall.vertex_attributes.at("cavity");
  const auto& tri = wall.triangles.at(static_cast<std::size_t>(near.triangle));
  return cavity[tri[0]] == 1.0 && cavity[tri[1]] == 1.0 && cavity[tri[2]] == 1.0;
}

QString disagreement(studio::MainWindow& window) {
  const studio::ViewState state = studio::view_state_of(window.document().files());
  for (const auto& object : window.document().scenario().objects) {
    const QString id = QString::fromStdString(object.id);
    const bool model = state.visible(object.id);
    QTreeWidgetItem* item = window.scene_tree()->visibility_item(id);
    if (item == nullptr) return id + ": no box";
    if ((item->checkState(0) == Qt::Checked) != model) return id + ": box differs";
    if (window.scene_view()->object_visible(id) != model) return id + ": view differs";
    if (std::abs(window.scene_view()->object_opacity(id) - state.opacity_of(object.id)) > 1e-9)
      return id + ": opacity differs";
  }
  for (const auto& tree : window.document().scenario().vessel_trees) {
    const QString key = QString::fromStdString(studio::vessel_tree_key(tree.id));
    const bool model = state.visible(studio::vessel_tree_key(tree.id));
    QTreeWidgetItem* item = window.scene_tree()->visibility_item(key);
    if (item == nullptr) return key + ": no box";
    if ((item->checkState(0) == Qt::Checked) != model) return key + ": box differs";
    if (window.scene_view()->vessel_tree_visible(QString::fromStdString(tree.id)) != model)
      return key + ": view differs";
  }
  return {};
}

}  // namespace viscera::studio_tests
