#include "simulator/view/blood_billboards.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPointGaussianMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace viscera::view {

BloodBillboards::BloodBillboards(vtkRenderer* scene)
    : points_(vtkSmartPointer<vtkPoints>::New()),
      stage_(vtkSmartPointer<vtkFloatArray>::New()),
      radius_(vtkSmartPointer<vtkFloatArray>::New()),
      cloud_(vtkSmartPointer<vtkPolyData>::New()),
      mapper_(vtkSmartPointer<vtkPointGaussianMapper>::New()),
      actor_(vtkSmartPointer<vtkActor>::New()) {
  points_->SetDataTypeToDouble();
  stage_->SetName("stage");
  radius_->SetName("radius");
  cloud_->SetPoints(points_);
  cloud_->GetPointData()->AddArray(stage_);
  cloud_->GetPointData()->AddArray(radius_);
  cloud_->GetPointData()->SetActiveScalars("stage");

  // Stage 0 → 1: bright arterial red, opaque, to dark venous red, faint.
  vtkNew<vtkLookupTable> stages;
  stages->SetNumberOfTableValues(64);
  for (int i = 0; i < 64; ++i) {
    const double s = i / 63.0;
    stages->SetTableValue(i, 0.72 - 0.40 * s, 0.03 + 0.02 * s, 0.03 + 0.02 * s, 0.85 - 0.70 * s);
  }
  stages->SetTableRange(0.0, 1.0);
  stages->Build();
  mapper_->SetInputData(cloud_);
  mapper_->SetLookupTable(stages);
  mapper_->SetScalarModeToUsePointFieldData();
  mapper_->SelectColorArray("stage");
  mapper_->SetScalarRange(0.0, 1.0);
  mapper_->SetColorModeToMapScalars();
  mapper_->ScalarVisibilityOn();
  mapper_->SetScaleArray("radius");
  mapper_->SetScaleFactor(1.0);
  mapper_->EmissiveOff();
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetOpacity(0.999);  // drawn in the translucent pass, blended
  actor_->SetVisibility(false);
  scene->AddActor(actor_);
}

BloodBillboards::~BloodBillboards() = default;

void BloodBillboards::update(const std::vector<core::Vec3>& positions,
                             const std::vector<float>& stages) {
  const auto n = static_cast<vtkIdType>(std::min(positions.size(), stages.size()));
  points_->SetNumberOfPoints(n);
  stage_->SetNumberOfTuples(n);
  radius_->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const float s = std::clamp(stages[u], 0.0f, 1.0f);
    points_->SetPoint(i, positions[u].data());
    stage_->SetValue(i, s);
    radius_->SetValue(i, static_cast<float>(kBirthRadius + (kDeathRadius - kBirthRadius) *
                                                               static_cast<double>(s)));
  }
  points_->Modified();
  stage_->Modified();
  radius_->Modified();
  cloud_->Modified();
  actor_->SetVisibility(n > 0);
}

std::size_t BloodBillboards::size() const {
  return static_cast<std::size_t>(points_->GetNumberOfPoints());
}

}  // namespace viscera::view
