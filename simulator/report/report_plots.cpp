#include "simulator/report/report_plots.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"
#include "simulator/view/image_files.h"
#include "simulator/view/x_display.h"

namespace viscera::report {

namespace {

using nlohmann::json;

const json& member(const json& object, const std::string& key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw core::InputError("the session report has no \"" + key + "\"", {"", where, ""});
  return object.at(key);
}

/// A table of named double columns of equal length.
vtkSmartPointer<vtkTable> table(
    const std::vector<std::pair<std::string, std::vector<double>>>& columns) {
  auto out = vtkSmartPointer<vtkTable>::New();
  for (const auto& [name, values] : columns) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(name.c_str());
    array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
      array->SetValue(static_cast<vtkIdType>(i), values[i]);
    out->AddColumn(array);
  }
  return out;
}

/// An offscreen chart: build it, then render() writes the PNG.
struct Chart {
  vtkNew<vtkContextView> view;
  vtkNew<vtkChartXY> chart;

  Chart(const std::string& title, const std::string& x, const std::string& y, PlotSize size) {
    view::require_x_display();  // VTK would end the process without one
    view->GetRenderWindow()->SetOffScreenRendering(1);
    view->GetRenderWindow()->SetSize(size.width, size.height);
    view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    view->GetScene()->AddItem(chart);
    chart->SetTitle(title);
    chart->GetTitleProperties()->SetFontSize(16);
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(x);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(y);
    chart->SetShowLegend(true);
  }
  vtkPlot* line(vtkTable* data, int x, int y, const unsigned char rgb[3], float width) {
    vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(data, x, y);
    plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
    plot->SetWidth(width);
    return plot;
  }
  void render(const std::filesystem::path& png) {
    view->GetRenderWindow()->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view->GetRenderWindow());
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    view::write_file_atomically(png, view::encode_png(grab->GetOutput()));
    view->GetRenderWindow()->Finalize();
  }
};

constexpr unsigned char kTrainee[3] = {200, 40, 40};
constexpr unsigned char kReference[3] = {150, 150, 150};
constexpr unsigned char kWarning[3] = {240, 160, 0};
constexpr unsigned char kBlood[3] = {120, 0, 20};

int axis_of(char c) {
  return c == 'x' ? 0 : c == 'y' ? 1 : 2;
}

}  // namespace

void plot_tool_path(const json& report, const json* reference, const std::string& plane,
                    const std::filesystem::path& png, PlotSize size) {
  if (plane.size() != 2) throw core::UsageError("a path plane is two axes, e.g. \"xy\"");
  const int a = axis_of(plane[0]), b = axis_of(plane[1]);
  const std::string names[3] = {"x (mm)", "y (mm)", "z (mm)"};
  Chart chart(plane == "xy" ? "Tool path seen from above, coloured by distance to the wall"
                            : "Tool path seen from the side, coloured by distance to the wall",
              names[a], names[b], size);
  if (reference != nullptr) {
    const json& tips = member(member(*reference, "path", "/path"), "tip", "/path/tip");
    std::vector<double> u, v;
    for (const auto& tip : tips) {
      u.push_back(1000.0 * tip.at(static_cast<std::size_t>(a)).get<double>());
      v.push_back(1000.0 * tip.at(static_cast<std::size_t>(b)).get<double>());
    }
    auto data = table({{"reference " + names[a], u}, {"reference path", v}});
    if (!u.empty()) chart.line(data, 0, 1, kReference, 1.5f);
  }
  const json& path = member(report, "path", "/path");
  const json& tips = member(path, "tip", "/path/tip");
  const json& distances = member(path, "wall_distance", "/path/wall_distance");
  std::vector<double> u, v, d;
  double far = 1.0;
  for (std::size_t i = 0; i < tips.size(); ++i) {
    u.push_back(1000.0 * tips[i].at(static_cast<std::size_t>(a)).get<double>());
    v.push_back(1000.0 * tips[i].at(static_cast<std::size_t>(b)).get<double>());
    const double mm = 1000.0 * std::max(0.0, distances.at(i).get<double>());
    d.push_back(mm);
    far = std::max(far, mm);
  }
  auto data = table({{names[a], u}, {"tool path", v}, {"wall distance (mm)", d}});
  if (!u.empty()) {
    auto* points = vtkPlotPoints::SafeDownCast(chart.chart->AddPlot(vtkChart::POINTS));
    points->SetInputData(data, 0, 1);
    vtkNew<vtkLookupTable> colours;
    colours->SetTableRange(0.0, far);
    colours->SetHueRange(0.0, 0.66);  // red at the wall, blue far from it
    colours->Build();
    points->SetLookupTable(colours);
    points->SelectColorArray("wall distance (mm)");
    points->ScalarVisibilityOn();
    points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    points->SetMarkerSize(5.0f);
  }
  chart.render(png);
}

void plot_force(const json& report, const json* reference, const std::filesystem::path& png,
                PlotSize size) {
  Chart chart("Force on the instrument over time", "time (s)", "force (N)", size);
  double end = 0.0;
  const auto series = [&](const json& r, const std::string& name, const unsigned char rgb[3],
                          float width) {
    const json& path = member(r, "path", "/path");
    std::vector<double> t = member(path, "time", "/path/time").get<std::vector<double>>();
    std::vector<double> f = member(path, "force", "/path/force").get<std::vector<double>>();
    if (t.empty()) return;
    end = std::max(end, t.back());
    chart.line(table({{"time (s)", t}, {name, f}}), 0, 1, rgb, width);
  };
  if (reference != nullptr) series(*reference, "reference", kReference, 1.5f);
  series(report, "trainee", kTrainee, 2.0f);
  const double warning = report.value("force_warning", 0.0);
  if (warning > 0.0 && end > 0.0) {
    vtkPlot* level =
        chart.line(table({{"time (s)", {0.0, end}}, {"warning level", {warning, warning}}}), 0, 1,
                   kWarning, 1.5f);
    level->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }
  chart.render(png);
}

bool plot_fluid(const json& report, const json* reference, const std::filesystem::path& png,
                PlotSize size) {
  const json& fluid = member(report, "fluid_series", "/fluid_series");
  if (fluid.is_null()) return false;
  Chart chart("Distension fluid deficit and blood in the cavity over time", "time (s)", "ml", size);
  const auto millilitres = [](const json& series, const char* key) {
    std::vector<double> values =
        member(series, key, std::string("/fluid_series/") + key).get<std::vector<double>>();
    for (double& v : values)
      v *= 1e6;
    return values;
  };
  if (reference != nullptr && reference->contains("fluid_series") &&
      !(*reference)["fluid_series"].is_null()) {
    const json& other = (*reference)["fluid_series"];
    chart.line(
        table({{"time (s)", member(other, "time", "/fluid_series/time").get<std::vector<double>>()},
               {"reference deficit", millilitres(other, "deficit")}}),
        0, 1, kReference, 1.5f);
  }
  const std::vector<double> t =
      member(fluid, "time", "/fluid_series/time").get<std::vector<double>>();
  chart.line(table({{"time (s)", t}, {"deficit", millilitres(fluid, "deficit")}}), 0, 1, kTrainee,
             2.0f);
  chart.line(table({{"time (s)", t}, {"blood in the cavity", millilitres(fluid, "bled")}}), 0, 1,
             kBlood, 2.0f);
  chart.render(png);
  return true;
}

namespace {

/// A score to draw: its value, or 0 when absent (the label then says "not assessed").
double drawn_score(const json& score) {
  return score.is_number() ? score.get<double>() : 0.0;
}

}  // namespace

void plot_step_scores(const json& report, const json* reference, const std::filesystem::path& png,
                      PlotSize size) {
  Chart chart("Score per procedure step (0-100)", "", "score", size);
  std::vector<std::string> labels;
  std::vector<double> scores;
  for (const auto& step : member(report, "procedure_steps", "/procedure_steps")) {
    const json score = step.value("score", json());
    labels.push_back((step.value("name", std::string()).empty() ? step.value("id", std::string("?"))
                                                                : step["name"].get<std::string>()) +
                     (score.is_number() ? "" : " (not assessed)"));
    scores.push_back(drawn_score(score));
  }
  const json whole = member(report, "score", "/score");
  labels.push_back(whole.is_number() ? "whole session" : "whole session (not assessed)");
  scores.push_back(drawn_score(whole));
  std::vector<double> x(scores.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = static_cast<double>(i + 1);
  std::vector<std::pair<std::string, std::vector<double>>> columns = {{"step", x},
                                                                      {"trainee", scores}};
  if (reference != nullptr) {
    std::vector<double> expert;
    for (const auto& step : member(*reference, "procedure_steps", "/procedure_steps"))
      expert.push_back(drawn_score(step.value("score", json())));
    expert.resize(scores.size() - 1, 0.0);
    expert.push_back(drawn_score(member(*reference, "score", "/score")));
    columns.emplace_back("reference", expert);
  }
  auto data = table(columns);
  vtkPlot* bars = chart.chart->AddPlot(vtkChart::BAR);
  bars->SetInputData(data, 0, 1);
  bars->SetColor(kTrainee[0], kTrainee[1], kTrainee[2], 255);
  if (reference != nullptr) {
    vtkPlot* expert = chart.chart->AddPlot(vtkChart::BAR);
    expert->SetInputData(data, 0, 2);
    expert->SetColor(kReference[0], kReference[1], kReference[2], 255);
  }
  vtkAxis* bottom = chart.chart->GetAxis(vtkAxis::BOTTOM);
  vtkNew<vtkDoubleArray> positions;
  vtkNew<vtkStringArray> names;
  for (std::size_t i = 0; i < x.size(); ++i) {
    positions->InsertNextValue(x[i]);
    names->InsertNextValue(labels[i]);
  }
  bottom->SetCustomTickPositions(positions, names);
  bottom->SetRange(0.4, static_cast<double>(x.size()) + 0.6);
  bottom->SetBehavior(vtkAxis::FIXED);
  bottom->GetLabelProperties()->SetOrientation(20.0);
  vtkAxis* left = chart.chart->GetAxis(vtkAxis::LEFT);
  left->SetRange(0.0, 100.0);
  left->SetBehavior(vtkAxis::FIXED);
  chart.render(png);
}

}  // namespace viscera::report
