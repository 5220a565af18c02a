#include "studio/ui/variants_gallery.h"

#include <QLabel>
#include <QListWidget>
#include <QPainter>
#include <QVBoxLayout>

#include "textures/surface_thumbnail.h"

namespace viscera::studio {

QImage scenario_thumbnail(const core::Scenario& scenario, int size) {
  core::SurfaceMesh all;
  for (const auto& object : scenario.objects) {
    const auto offset = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), object.surface.vertices.begin(),
                        object.surface.vertices.end());
    for (const auto& t : object.surface.triangles)
      all.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  if (all.triangles.empty()) {
    QImage empty(size, size, QImage::Format_RGB888);
    empty.fill(QColor(40, 44, 52));
    return empty;
  }
  const textures::Image8 image = textures::render_surface_thumbnail(all, size);
  return QImage(image.pixels.data(), image.width, image.height, image.width * image.channels,
                QImage::Format_RGB888)
      .copy();
}

QImage badged_thumbnail(const QImage& thumbnail, bool valid) {
  QImage out = thumbnail.convertToFormat(QImage::Format_RGB888);
  QPainter painter(&out);
  painter.setRenderHint(QPainter::Antialiasing);
  const int r = std::max(8, out.width() / 7);
  const QRectF badge(out.width() - 2 * r - 3, 3, 2 * r, 2 * r);
  painter.setPen(Qt::NoPen);
  painter.setBrush(valid ? QColor(40, 160, 70) : QColor(200, 40, 40));
  painter.drawEllipse(badge);
  QPen mark(Qt::white, std::max(2.0, r / 3.5));
  mark.setCapStyle(Qt::RoundCap);
  painter.setPen(mark);
  const QPointF c = badge.center();
  if (valid) {
    painter.drawPolyline(QPolygonF({c + QPointF(-0.5 * r, 0.0), c + QPointF(-0.1 * r, 0.4 * r),
                                    c + QPointF(0.5 * r, -0.4 * r)}));
  } else {
    painter.drawLine(c + QPointF(-0.4 * r, -0.4 * r), c + QPointF(0.4 * r, 0.4 * r));
    painter.drawLine(c + QPointF(-0.4 * r, 0.4 * r), c + QPointF(0.4 * r, -0.4 * r));
  }
  return out;
}

VariantsGallery::VariantsGallery(QWidget* parent) : QWidget(parent) {
  header_ = new QLabel(tr("Use Create ▸ Generate variants… to fill the gallery."), this);
  header_->setWordWrap(true);
  list_ = new QListWidget(this);
  list_->setViewMode(QListView::IconMode);
  list_->setIconSize(QSize(128, 128));
  list_->setResizeMode(QListView::Adjust);
  list_->setMovement(QListView::Static);
  list_->setSpacing(4);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(header_);
  layout->addWidget(list_);
  connect(list_, &QListWidget::itemDoubleClicked, this,
          [this](QListWidgetItem* item) { emit open_requested(list_->row(item)); });
}

void VariantsGallery::set_variants(std::vector<GalleryEntry> entries, PackageFiles files,
                                   const QString& description) {
  entries_ = std::move(entries);
  files_ = std::move(files);
  list_->clear();
  int passed = 0;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Variant& v = entries_[i].variant;
    passed += v.valid ? 1 : 0;
    auto* item = new QListWidgetItem(
        QIcon(QPixmap::fromImage(badged_thumbnail(entries_[i].thumbnail, v.valid))),
        tr("variant %1").arg(v.index), list_);
    item->setToolTip(tooltip(static_cast<int>(i)));
    item->setData(Qt::UserRole, v.valid);
  }
  header_->setText(
      tr("%1 — %2 of %3 passed validation").arg(description).arg(passed).arg(entries_.size()));
}

QString VariantsGallery::tooltip(int row) const {
  const Variant& v = variant(row);
  const QString draws = tr("%n draw(s), seed %1", nullptr, v.attempts).arg(v.draw_seed);
  if (v.valid) return tr("Variant %1 passed every check (%2)").arg(v.index).arg(draws);
  QString text = tr("Variant %1 failed %2 (%3)")
                     .arg(v.index)
                     .arg(QString::fromStdString(v.failure))
                     .arg(draws);
  if (!v.scenario) text += tr("; no patient could be built to open");
  return text;
}

}  // namespace viscera::studio
