#include "simulator/view/session_overlay.h"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace viscera::view {

namespace {

// Bars in normalised viewport coordinates, right of the round field.
constexpr double kBarLeft = 0.885, kBarWidth = 0.018, kBarGap = 0.008;
constexpr double kBarBottom = 0.12, kBarHeight = 0.55;
// Seed 002 §5.2's colours: green, blue, yellow, red.
constexpr unsigned char kColours[4][3] = {
    {60, 200, 80}, {70, 120, 240}, {235, 210, 50}, {230, 50, 40}};

vtkSmartPointer<vtkTextActor> text(double x, double y, int size, double r, double g, double b) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  vtkTextProperty* property = actor->GetTextProperty();
  property->SetFontFamilyToCourier();
  property->SetFontSize(size);
  property->SetColor(r, g, b);
  property->SetShadow(1);
  return actor;
}

void set_quad(vtkPoints* points, vtkIdType first, double x0, double y0, double x1, double y1) {
  points->SetPoint(first + 0, x0, y0, 0.0);
  points->SetPoint(first + 1, x1, y0, 0.0);
  points->SetPoint(first + 2, x1, y1, 0.0);
  points->SetPoint(first + 3, x0, y1, 0.0);
}

}  // namespace

std::string force_alert(double force, double warning) {
  if (!(warning > 0.0)) return "";
  if (force > warning) return "excessive";
  if (force > 0.8 * warning) return "approaching";
  return "";
}

SessionOverlay::SessionOverlay(const std::string& bindings) {
  info_ = text(0.01, 0.70, 15, 0.9, 0.95, 0.9);
  bindings_ = text(0.01, 0.01, 12, 0.75, 0.8, 0.85);
  bindings_->SetInput(bindings.c_str());
  bindings_->SetVisibility(bindings.empty() ? 0 : 1);
  warning_ = text(0.5, 0.92, 22, 1.0, 0.25, 0.2);
  warning_->GetTextProperty()->SetJustificationToCentered();
  warning_->GetTextProperty()->BoldOn();
  legend_ = text(kBarLeft - 0.002, kBarBottom - 0.05, 12, 0.85, 0.85, 0.85);
  legend_->SetInput("Fx Fy Fz |F|");

  // 4 backgrounds, 4 bars, 1 warning tick: 9 quads.
  bars_ = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(36);
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (vtkIdType q = 0; q < 9; ++q) {
    const vtkIdType ids[4] = {4 * q, 4 * q + 1, 4 * q + 2, 4 * q + 3};
    quads->InsertNextCell(4, ids);
    if (q < 4) {
      colours->InsertNextTuple3(40, 40, 40);
    } else if (q < 8) {
      const auto* c = kColours[q - 4];
      colours->InsertNextTuple3(c[0], c[1], c[2]);
    } else {
      colours->InsertNextTuple3(255, 255, 255);
    }
  }
  bars_->SetPoints(points);
  bars_->SetPolys(quads);
  bars_->GetCellData()->SetScalars(colours);
  vtkNew<vtkCoordinate> coordinate;
  coordinate->SetCoordinateSystemToNormalizedViewport();
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(bars_);
  mapper->SetTransformCoordinate(coordinate);
  mapper->SetScalarModeToUseCellData();
  bar_actor_ = vtkSmartPointer<vtkActor2D>::New();
  bar_actor_->SetMapper(mapper);
  update(OverlayState{});
}

SessionOverlay::~SessionOverlay() = default;

void SessionOverlay::add_to(vtkRenderer* renderer) const {
  renderer->AddActor2D(bar_actor_);
  renderer->AddActor2D(info_);
  renderer->AddActor2D(bindings_);
  renderer->AddActor2D(warning_);
  renderer->AddActor2D(legend_);
}

void SessionOverlay::lay_out_info(const OverlayState& state, double magnitude,
                                  const std::string& tool) {
  char buffer[640];
  std::snprintf(buffer, sizeof buffer,
                "Elapsed %6.1f s / %.1f s\n"
                "Force   %5.2f N  (%+.2f %+.2f %+.2f)\n"
                "Tip     %+6.1f %+6.1f %+6.1f mm\n"
                "Optics  %.0f deg   inflow %.0f%%  outflow %.0f%%\n"
                "Seen    %4.1f %% of the cavity\n"
                "Step    %s%s%s%s",
                state.elapsed, state.time_limit, magnitude, state.force.x(), state.force.y(),
                state.force.z(), 1000.0 * state.tip.x(), 1000.0 * state.tip.y(),
                1000.0 * state.tip.z(), state.optics_angle, 100.0 * state.inflow,
                100.0 * state.outflow, 100.0 * state.surface_seen,
                state.step.empty() ? "-" : state.step.c_str(),
                state.ended.empty() ? "" : "\nEnded   ", state.ended.c_str(), tool.c_str());
  info_->SetInput(buffer);
}

void SessionOverlay::update(const OverlayState& state) {
  const double magnitude = state.force.norm();
  // Full scale: 1.5 × the warning level, or 2 N without one.
  const double full = state.force_warning > 0.0 ? 1.5 * state.force_warning : 2.0;
  const double values[4] = {std::abs(state.force.x()), std::abs(state.force.y()),
                            std::abs(state.force.z()), magnitude};
  vtkPoints* points = bars_->GetPoints();
  for (int b = 0; b < 4; ++b) {
    fill_[static_cast<std::size_t>(b)] = std::clamp(values[b] / full, 0.0, 1.0);
    const double x0 = kBarLeft + b * (kBarWidth + kBarGap);
    set_quad(points, 4 * b, x0, kBarBottom, x0 + kBarWidth, kBarBottom + kBarHeight);
    set_quad(points, 16 + 4 * b, x0, kBarBottom, x0 + kBarWidth,
             kBarBottom + kBarHeight * fill_[static_cast<std::size_t>(b)]);
  }
  const double tick = state.force_warning > 0.0 ? kBarBottom + kBarHeight / 1.5 : -1.0;
  set_quad(points, 32, kBarLeft - 0.004, tick - 0.002, kBarLeft + 4 * (kBarWidth + kBarGap),
           tick + 0.002);
  points->Modified();
  bars_->Modified();

  std::string tool;
  if (!state.tool.empty()) {
    if (state.tool == "suction")  // a suction–irrigation cannula: two valves, no jaws
      tool = std::string("\nTool    suction ") + (state.jaws_closed ? "on" : "off") +
             ", irrigation " + (state.irrigating ? "on" : "off");
    else
      tool = "\nTool    " + state.tool + ", jaws " + (state.jaws_closed ? "closed" : "open");
    if (state.pool_ml >= 0.5)
      tool += "   pool " + std::to_string(std::lround(state.pool_ml)) + " ml (" +
              std::to_string(std::lround(100.0 * state.pool_blood_fraction)) + " % blood)";
    if (state.lens_fog > 0.05)
      tool += "   lens steamed " + std::to_string(std::lround(100.0 * state.lens_fog)) + " %";
    if (!state.left_tool.empty())
      tool +=
          "\nLeft    " + state.left_tool + ", jaws " + (state.left_jaws_closed ? "closed" : "open");
  }
  const std::string lines = state.step + "\n" + state.ended + "\n" + tool;
  const bool due = laid_out_at_ < 0.0 || state.elapsed < laid_out_at_ ||
                   state.elapsed >= laid_out_at_ + kTextInterval || lines != laid_out_lines_;
  if (due) {
    lay_out_info(state, magnitude, tool);
    laid_out_at_ = state.elapsed;
    laid_out_lines_ = lines;
  }

  const std::string alert = force_alert(magnitude, state.force_warning);
  if (alert == "excessive") {
    warning_->SetInput("EXCESSIVE FORCE - tissue at risk");
    warning_->GetTextProperty()->SetColor(1.0, 0.2, 0.15);
  } else if (alert == "approaching") {
    warning_->SetInput("Force approaching the tissue limit");
    warning_->GetTextProperty()->SetColor(1.0, 0.8, 0.2);
  } else {
    warning_->SetInput("");
  }
}

std::string SessionOverlay::info_text() const {
  return info_->GetInput();
}
std::string SessionOverlay::warning_text() const {
  return warning_->GetInput();
}

}  // namespace viscera::view
