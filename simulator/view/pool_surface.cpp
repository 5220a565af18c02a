#include "simulator/view/pool_surface.h"

#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderer.h>

#include <algorithm>

namespace viscera::view {

PoolSurface::PoolSurface(vtkRenderer* scene) {
  disc_ = vtkSmartPointer<vtkRegularPolygonSource>::New();
  disc_->SetNumberOfSides(64);
  disc_->GeneratePolygonOn();
  disc_->GeneratePolylineOff();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(disc_->GetOutputPort());
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
  disc_->SetCenter(centre.x(), centre.y(), centre.z());
  disc_->SetNormal(up.x(), up.y(), up.z());
  disc_->SetRadius(radius);
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
