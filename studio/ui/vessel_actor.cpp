#include "studio/ui/vessel_actor.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTubeFilter.h>

namespace viscera::studio {

vtkSmartPointer<vtkActor> vessel_tree_actor(const core::VesselTree& tree) {
  if (tree.segments.empty()) return nullptr;
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName("radius");
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& segment : tree.segments) {
    const vtkIdType a = points->InsertNextPoint(segment.proximal.data());
    const vtkIdType b = points->InsertNextPoint(segment.distal.data());
    radii->InsertNextValue(segment.radius);
    radii->InsertNextValue(segment.radius);
    const vtkIdType line[2] = {a, b};
    lines->InsertNextCell(2, line);
  }
  auto centre_lines = vtkSmartPointer<vtkPolyData>::New();
  centre_lines->SetPoints(points);
  centre_lines->SetLines(lines);
  centre_lines->GetPointData()->SetScalars(radii);
  auto tubes = vtkSmartPointer<vtkTubeFilter>::New();
  tubes->SetInputData(centre_lines);
  tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
  tubes->SetNumberOfSides(8);
  tubes->CappingOn();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(tubes->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPickable(false);
  if (tree.kind == "venous") {
    actor->GetProperty()->SetColor(0.25, 0.30, 0.70);
  } else {
    actor->GetProperty()->SetColor(0.75, 0.10, 0.12);
  }
  return actor;
}

}  // namespace viscera::studio
