#include "simulator/view/pool_surface.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace viscera::view {

PoolSurface::PoolSurface(vtkRenderer* scene) {
  rim_ = vtkSmartPointer<vtkPoints>::New();
  rim_->SetNumberOfPoints(kSides);
  vtkNew<vtkCellArray> polygon;
  polygon->InsertNextCell(kSides);
  for (vtkIdType i = 0; i < kSides; ++i)
    polygon->InsertCellPoint(i);
  vtkNew<vtkPolyData> disc;
  disc->SetPoints(rim_);
  disc->SetPolys(polygon);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(disc);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  vtkProperty* look = actor_->GetProperty();
  look->SetAmbient(0.3);
  look->SetDiffuse(0.5);
  look->SetSpecular(0.6);  // a wet surface catches the head light
  look->SetSpecularPower(60.0);
  look->BackfaceCullingOff();
  actor_->SetVisibility(false);
  scene->AddActor(actor_);
}

PoolSurface::~PoolSurface() = default;

void PoolSurface::update(const core::Vec3& centre, const core::Vec3& up, double radius,
                         double blood_fraction) {
  if (!(radius > 0.0) || !(up.norm() > 0.0)) {
    actor_->SetVisibility(false);
    return;
  }
  // Two directions across `up` span the disc.
  const core::Vec3 n = up.normalized();
  const core::Vec3 u = n.unitOrthogonal(), v = n.cross(u);
  for (int i = 0; i < kSides; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / kSides;
    const core::Vec3 p = centre + radius * (std::cos(angle) * u + std::sin(angle) * v);
    rim_->SetPoint(i, p.data());
  }
  rim_->Modified();
  const double b = std::clamp(blood_fraction, 0.0, 1.0);
  vtkProperty* look = actor_->GetProperty();
  look->SetColor(0.72 - 0.30 * b, 0.80 - 0.77 * b, 0.86 - 0.82 * b);
  look->SetOpacity(0.45 + 0.4 * b);
  actor_->SetVisibility(true);
}

bool PoolSurface::visible() const {
  return actor_->GetVisibility() != 0;
}

}  // namespace viscera::view
