#include "exporters/vtk_legacy_writer.h"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>

#include "core/error.h"
#include "core/package/vtk_mesh_io.h"
#include "core/vtk_silence.h"

namespace viscera::exporters {
namespace {

template <typename Writer>
void write_42(Writer& writer, const std::filesystem::path& path, const std::string& shown) {
  writer.SetFileName(path.string().c_str());
  writer.SetFileTypeToASCII();
  writer.SetFileVersion(vtkDataWriter::VTK_LEGACY_READER_VERSION_4_2);
  const core::ScopedVtkSilence silence;
  if (writer.Write() != 1)
    throw core::OutputError("VTK cannot write " + path.filename().string(), {shown, "", ""});
}

}  // namespace

void write_legacy_vtk_surface(const core::SurfaceMesh& surface, const std::filesystem::path& path,
                              const std::string& shown) {
  vtkNew<vtkPolyData> polydata;
  core::surface_to_polydata(surface, {}, *polydata);
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputData(polydata);
  write_42(*writer, path, shown);
}

void write_legacy_vtk_tets(const core::TetMesh& body, bool arrays,
                           const std::filesystem::path& path, const std::string& shown) {
  vtkNew<vtkUnstructuredGrid> grid;
  if (arrays) {
    core::tet_mesh_to_grid(body, *grid);
  } else {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(body.nodes.size()));
    for (std::size_t i = 0; i < body.nodes.size(); ++i)
      points->SetPoint(static_cast<vtkIdType>(i), body.nodes[i].data());
    grid->SetPoints(points);
    grid->Allocate(static_cast<vtkIdType>(body.tets.size()));
    for (const auto& tet : body.tets) {
      const vtkIdType ids[4] = {tet[0], tet[1], tet[2], tet[3]};
      grid->InsertNextCell(VTK_TETRA, 4, ids);
    }
  }
  vtkNew<vtkUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  write_42(*writer, path, shown);
}

}  // namespace viscera::exporters
