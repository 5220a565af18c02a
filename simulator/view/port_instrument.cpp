#include "simulator/view/port_instrument.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <array>
#include <cmath>
#include <numbers>

namespace viscera::view {

namespace {

constexpr int kShaftSides = 12;

/// Appends a box: centre `c`, half-extents `h` along the orthonormal `a`, `b`, `n`.
void add_box(vtkPoints* points, vtkCellArray* polys, const core::Vec3& c, const core::Vec3& a,
             const core::Vec3& b, const core::Vec3& n, const core::Vec3& h) {
  const vtkIdType first = points->GetNumberOfPoints();
  for (int k = 0; k < 8; ++k) {
    const core::Vec3 p = c + ((k & 1) ? h.x() : -h.x()) * a + ((k & 2) ? h.y() : -h.y()) * b +
                         ((k & 4) ? h.z() : -h.z()) * n;
    points->InsertNextPoint(p.data());
  }
  static constexpr std::array<std::array<int, 4>, 6> kFaces = {
      {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& f : kFaces) {
    const vtkIdType quad[4] = {first + f[0], first + f[1], first + f[2], first + f[3]};
    polys->InsertNextCell(4, quad);
  }
}

bool has_jaws(sim::LaparoscopicTool tool) {
  return tool == sim::LaparoscopicTool::Grasper || tool == sim::LaparoscopicTool::ClipApplier ||
         tool == sim::LaparoscopicTool::Scissors || tool == sim::LaparoscopicTool::Bipolar;
}

}  // namespace

vtkSmartPointer<vtkPolyData> port_instrument_mesh(const sim::SecondPort& port,
                                                  const PortInstrumentShape& shape) {
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  if (port.inserted) {
    const core::Vec3 axis = port.axis.normalized();
    core::Vec3 up = port.up - port.up.dot(axis) * axis;
    up = up.norm() > 1e-12 ? up.normalized() : axis.unitOrthogonal();
    const core::Vec3 side = axis.cross(up);
    const bool jaws = has_jaws(port.tool);
    const core::Vec3 end = jaws ? core::Vec3(port.tip - shape.jaw_length * axis) : port.tip;
    const core::Vec3 start = end - shape.shaft_length * axis;
    // The shaft: a prism of kShaftSides sides, closed at the hinge.
    const vtkIdType first = points->GetNumberOfPoints();
    for (int ring = 0; ring < 2; ++ring)
      for (int k = 0; k < kShaftSides; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / kShaftSides;
        const core::Vec3 p = (ring == 0 ? start : end) +
                             shape.shaft_radius * (std::cos(angle) * up + std::sin(angle) * side);
        points->InsertNextPoint(p.data());
      }
    for (int k = 0; k < kShaftSides; ++k) {
      const int next = (k + 1) % kShaftSides;
      const vtkIdType quad[4] = {first + k, first + next, first + kShaftSides + next,
                                 first + kShaftSides + k};
      polys->InsertNextCell(4, quad);
    }
    std::array<vtkIdType, kShaftSides> cap{};
    for (int k = 0; k < kShaftSides; ++k)
      cap[static_cast<std::size_t>(k)] = first + kShaftSides + k;
    polys->InsertNextCell(kShaftSides, cap.data());
    if (jaws) {
      // Each jaw hinges at the shaft's end and reaches the tip, opened half the opening to its
      // side of the axis (closed: they meet on it).
      const double half = port.jaws_closed ? 0.5 * shape.jaw_thickness : 0.5 * shape.jaw_opening;
      for (const double sign : {1.0, -1.0}) {
        const core::Vec3 jaw_tip = port.tip + sign * half * up;
        const core::Vec3 along = (jaw_tip - end).normalized();
        const core::Vec3 normal = along.cross(side).normalized();
        add_box(points, polys, 0.5 * (end + jaw_tip), along, side, normal,
                core::Vec3(0.5 * (jaw_tip - end).norm(), 0.8 * shape.shaft_radius,
                           0.5 * shape.jaw_thickness));
      }
    }
  }
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

PortInstrument::PortInstrument(vtkRenderer* scene) : actor_(vtkSmartPointer<vtkActor>::New()) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(port_instrument_mesh(sim::SecondPort{}));
  actor_->SetMapper(mapper);
  vtkProperty* steel = actor_->GetProperty();
  steel->SetColor(0.62, 0.64, 0.66);
  steel->SetSpecular(0.6);
  steel->SetSpecularPower(40.0);
  steel->SetAmbient(0.15);
  steel->SetDiffuse(0.7);
  actor_->VisibilityOff();
  scene->AddActor(actor_);
}

PortInstrument::~PortInstrument() = default;

void PortInstrument::update(const sim::SecondPort& port) {
  actor_->SetVisibility(port.inserted ? 1 : 0);
  if (!port.inserted || port == shown_) return;  // a tool held still keeps its triangles
  shown_ = port;
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor_->GetMapper());
  mapper->SetInputData(port_instrument_mesh(port));
}

bool PortInstrument::visible() const {
  return actor_->GetVisibility() != 0;
}

}  // namespace viscera::view
