#pragma once
/// A stress–strain plot (issue 9 §5; seed 001 §3.2): the measured samples as dots and the fitted
/// cubic σ(ε) = c1 ε + c2 ε|ε| + c3 ε³ as a curve, with axes in strain and kPa, drawn with
/// QPainter so it needs no OpenGL context of its own.

#include <QWidget>
#include <array>
#include <optional>
#include <vector>

namespace viscera::studio {

class StressStrainPlot : public QWidget {
  Q_OBJECT

 public:
  explicit StressStrainPlot(QWidget* parent = nullptr);

  /// Samples (strain, Pa) and the fit {c0, c1, c2, c3} in Pa (none: samples only).
  void set_data(std::vector<double> strain, std::vector<double> stress,
                std::optional<std::array<double, 4>> cubic);
  /// Widget pixel of (strain, stress Pa) in the current axes.
  QPointF to_pixel(double strain, double stress) const;

  /// Colours of the samples and of the fitted curve.
  static constexpr QRgb kSampleColour = 0xff1f5fbf;
  static constexpr QRgb kCurveColour = 0xffd0402a;

  QSize sizeHint() const override { return {320, 220}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QRectF plot_area() const;

  std::vector<double> strain_, stress_;
  std::optional<std::array<double, 4>> cubic_;
  double strain_min_ = 0.0, strain_max_ = 1.0, stress_min_ = 0.0, stress_max_ = 1.0;
};

}  // namespace viscera::studio
