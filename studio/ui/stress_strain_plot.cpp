#include "studio/ui/stress_strain_plot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "core/materials/cubic_stress_fit.h"

namespace viscera::studio {
namespace {

constexpr int kCurvePoints = 200;

}  // namespace

StressStrainPlot::StressStrainPlot(QWidget* parent) : QWidget(parent) {
  setMinimumSize(240, 160);
  setAutoFillBackground(true);
  QPalette p = palette();
  p.setColor(QPalette::Window, Qt::white);
  setPalette(p);
}

void StressStrainPlot::set_data(std::vector<double> strain, std::vector<double> stress,
                                std::optional<std::array<double, 4>> cubic) {
  strain_ = std::move(strain);
  stress_ = std::move(stress);
  cubic_ = cubic;
  // Axes cover the samples, the origin and the curve over the samples' strain range.
  strain_min_ = 0.0, strain_max_ = 0.0, stress_min_ = 0.0, stress_max_ = 0.0;
  for (std::size_t i = 0; i < strain_.size(); ++i) {
    strain_min_ = std::min(strain_min_, strain_[i]);
    strain_max_ = std::max(strain_max_, strain_[i]);
    stress_min_ = std::min(stress_min_, stress_[i]);
    stress_max_ = std::max(stress_max_, stress_[i]);
  }
  if (cubic_) {
    for (int k = 0; k <= kCurvePoints; ++k) {
      const double e = strain_min_ + (strain_max_ - strain_min_) * k / kCurvePoints;
      const double s = core::cubic_stress(*cubic_, e);
      stress_min_ = std::min(stress_min_, s);
      stress_max_ = std::max(stress_max_, s);
    }
  }
  if (strain_max_ - strain_min_ <= 0.0) strain_max_ = strain_min_ + 1.0;
  if (stress_max_ - stress_min_ <= 0.0) stress_max_ = stress_min_ + 1.0;
  const double margin = 0.05 * (stress_max_ - stress_min_);
  stress_max_ += margin;
  stress_min_ -= stress_min_ < 0.0 ? margin : 0.0;
  update();
}

QRectF StressStrainPlot::plot_area() const {
  return QRectF(56.0, 12.0, std::max(10.0, width() - 68.0), std::max(10.0, height() - 44.0));
}

QPointF StressStrainPlot::to_pixel(double strain, double stress) const {
  const QRectF area = plot_area();
  return {area.left() + area.width() * (strain - strain_min_) / (strain_max_ - strain_min_),
          area.bottom() - area.height() * (stress - stress_min_) / (stress_max_ - stress_min_)};
}

void StressStrainPlot::paintEvent(QPaintEvent* /*event*/) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  const QRectF area = plot_area();
  painter.setPen(QPen(Qt::black, 1.0));
  painter.drawRect(area);
  // Ticks: both ends of each axis, strain plain, stress in kPa.
  const QFontMetrics metrics(font());
  painter.drawText(QPointF(area.left(), area.bottom() + metrics.height()),
                   QString::number(strain_min_, 'g', 3));
  const QString right = QString::number(strain_max_, 'g', 3);
  painter.drawText(
      QPointF(area.right() - metrics.horizontalAdvance(right), area.bottom() + metrics.height()),
      right);
  painter.drawText(QPointF(area.center().x() - 20.0, height() - 4.0), tr("strain"));
  painter.drawText(QPointF(2.0, area.top() + metrics.ascent()),
                   QString::number(stress_max_ / 1000.0, 'g', 3));
  painter.drawText(QPointF(2.0, area.bottom()), QString::number(stress_min_ / 1000.0, 'g', 3));
  painter.drawText(QPointF(2.0, area.center().y()), tr("kPa"));

  if (cubic_) {
    QPainterPath path;
    for (int k = 0; k <= kCurvePoints; ++k) {
      const double e = strain_min_ + (strain_max_ - strain_min_) * k / kCurvePoints;
      const QPointF p = to_pixel(e, core::cubic_stress(*cubic_, e));
      if (k == 0) {
        path.moveTo(p);
      } else {
        path.lineTo(p);
      }
    }
    painter.setPen(QPen(QColor::fromRgba(kCurveColour), 2.0));
    painter.drawPath(path);
  }
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor::fromRgba(kSampleColour));
  for (std::size_t i = 0; i < strain_.size(); ++i)
    painter.drawEllipse(to_pixel(strain_[i], stress_[i]), 3.0, 3.0);
}

}  // namespace viscera::studio
