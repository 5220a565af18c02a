#include "simulator/view/particle_billboards.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace viscera::view {

ParticleBillboards::ParticleBillboards(vtkRenderer* scene, const ParticleLook& look) {
  for (int s = 0; s < kStages; ++s) {
    Stage& stage = stages_[static_cast<std::size_t>(s)];
    stage.points = vtkSmartPointer<vtkPoints>::New();
    stage.points->SetDataTypeToDouble();
    stage.vertices = vtkSmartPointer<vtkCellArray>::New();
    stage.cloud = vtkSmartPointer<vtkPolyData>::New();
    stage.cloud->SetPoints(stage.points);
    stage.cloud->SetVerts(stage.vertices);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(stage.cloud);
    mapper->ScalarVisibilityOff();
    stage.actor = vtkSmartPointer<vtkActor>::New();
    stage.actor->SetMapper(mapper);
    const double t = s / (kStages - 1.0);
    vtkProperty* property = stage.actor->GetProperty();
    property->SetColor(look.first_colour[0] + (look.last_colour[0] - look.first_colour[0]) * t,
                       look.first_colour[1] + (look.last_colour[1] - look.first_colour[1]) * t,
                       look.first_colour[2] + (look.last_colour[2] - look.first_colour[2]) * t);
    property->SetAmbient(look.ambient);
    property->SetDiffuse(1.0 - look.ambient);
    property->SetSpecular(look.spheres ? 0.8 : 0.0);
    property->SetSpecularPower(40.0);
    property->SetPointSize(
        static_cast<float>(look.first_size + (look.last_size - look.first_size) * t));
    property->SetRenderPointsAsSpheres(look.spheres);
    stage.actor->SetVisibility(false);
    scene->AddActor(stage.actor);
  }
}

ParticleBillboards::~ParticleBillboards() = default;

void ParticleBillboards::update(const std::vector<core::Vec3>& positions,
                                const std::vector<float>& stages) {
  const std::size_t n = std::min(positions.size(), stages.size());
  std::array<vtkIdType, kStages> counts{};
  const auto bin = [](float stage) {
    return std::clamp(static_cast<int>(std::clamp(stage, 0.0f, 1.0f) * kStages), 0, kStages - 1);
  };
  for (std::size_t i = 0; i < n; ++i)
    ++counts[static_cast<std::size_t>(bin(stages[i]))];
  for (int s = 0; s < kStages; ++s) {
    Stage& stage = stages_[static_cast<std::size_t>(s)];
    stage.points->SetNumberOfPoints(counts[static_cast<std::size_t>(s)]);
    stage.vertices->Reset();
  }
  std::array<vtkIdType, kStages> next{};
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = static_cast<std::size_t>(bin(stages[i]));
    stages_[s].points->SetPoint(next[s], positions[i].data());
    stages_[s].vertices->InsertNextCell(1, &next[s]);
    ++next[s];
  }
  size_ = n;
  for (Stage& stage : stages_) {
    stage.points->Modified();
    stage.vertices->Modified();
    stage.cloud->Modified();
    stage.actor->SetVisibility(stage.points->GetNumberOfPoints() > 0);
  }
}

}  // namespace viscera::view
