#include "simulator/view/pool_surface.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "simulator/runtime/session_snapshot.h"

namespace viscera::view {

namespace {

constexpr int kRings = sim::SessionSnapshot::kPoolRings;
constexpr int kSides = sim::SessionSnapshot::kPoolSides;

/// The vertex of ring k (1…kRings) at side s, 0 the centre.
vtkIdType vertex(int k, int s) {
  return k == 0 ? 0 : 1 + static_cast<vtkIdType>((k - 1) * kSides + (s % kSides));
}

}  // namespace

PoolSurface::PoolSurface(vtkRenderer* scene) {
  points_ = vtkSmartPointer<vtkPoints>::New();
  points_->SetNumberOfPoints(1 + kRings * kSides);
  vtkNew<vtkCellArray> triangles;
  for (int s = 0; s < kSides; ++s) {
    const vtkIdType fan[3] = {vertex(0, 0), vertex(1, s), vertex(1, s + 1)};
    triangles->InsertNextCell(3, fan);
    for (int k = 1; k < kRings; ++k) {
      const vtkIdType a[3] = {vertex(k, s), vertex(k + 1, s), vertex(k + 1, s + 1)};
      const vtkIdType b[3] = {vertex(k, s), vertex(k + 1, s + 1), vertex(k, s + 1)};
      triangles->InsertNextCell(3, a);
      triangles->InsertNextCell(3, b);
    }
  }
  surface_ = vtkSmartPointer<vtkPolyData>::New();
  surface_->SetPoints(points_);
  surface_->SetPolys(triangles);
  normals_ = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals_->SetInputData(surface_);
  normals_->SplittingOff();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(normals_->GetOutputPort());
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
                         double blood_fraction, std::span<const float> waves) {
  if (!(radius > 0.0) || !(up.norm() > 0.0)) {
    actor_->SetVisibility(false);
    return;
  }
  // Two directions across `up` span the disc (as fluid::PoolWaves lays its grid).
  const core::Vec3 n = up.normalized();
  const core::Vec3 u = n.unitOrthogonal(), v = n.cross(u);
  const bool waving = waves.size() == static_cast<std::size_t>(1 + kRings * kSides);
  double high = 0.0, low = 0.0;
  for (int k = 0; k <= kRings; ++k)
    for (int s = 0; s < (k == 0 ? 1 : kSides); ++s) {
      const vtkIdType id = vertex(k, s);
      const double angle = 2.0 * std::numbers::pi * s / kSides, r = radius * k / kRings;
      const double lift = waving ? static_cast<double>(waves[static_cast<std::size_t>(id)]) : 0.0;
      high = std::max(high, lift);
      low = std::min(low, lift);
      const core::Vec3 p = centre + r * (std::cos(angle) * u + std::sin(angle) * v) + lift * n;
      points_->SetPoint(id, p.data());
    }
  relief_ = high - low;
  points_->Modified();
  surface_->Modified();
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
