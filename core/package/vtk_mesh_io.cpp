#include "core/package/vtk_mesh_io.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <limits>

#include "core/crash_guard.h"
#include "core/error.h"
#include "core/vtk_silence.h"

namespace viscera::core {
namespace {

/// Component `c` of tuple `i` of an index array as an int. A damaged file may hold any double
/// there (the package_folder fuzz target's finding): it must be a whole number from −1 up that
/// an int holds before it is converted; range checks against the mesh follow later.
int index_in(vtkDataArray& array, vtkIdType i, int c, const std::string& name,
             const std::string& what) {
  const double value = array.GetComponent(i, c);
  if (!(value >= -1.0 && value <= static_cast<double>(std::numeric_limits<int>::max())) ||
      value != std::floor(value)) {
    throw InputError("\"" + name + "\" entry " + std::to_string(i) + " is not an index",
                     {what, "", ""});
  }
  return static_cast<int>(value);
}

vtkNew<vtkPoints> to_points(const std::vector<Vec3>& positions) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), positions[i].data());
  }
  return points;
}

std::vector<Vec3> from_points(vtkPoints* points) {
  std::vector<Vec3> positions;
  if (points == nullptr) return positions;
  positions.resize(static_cast<std::size_t>(points->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    points->GetPoint(i, positions[i].data());
  return positions;
}

vtkNew<vtkDoubleArray> double_array(const char* name, int components, std::size_t tuples) {
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
  return array;
}

/// An array of `what` with the expected component count and tuple count, or nullptr if absent.
vtkDataArray* checked_array(vtkFieldData* data, const char* name, int components, vtkIdType tuples,
                            const std::string& what) {
  vtkDataArray* array = data->GetArray(name);
  if (array == nullptr) return nullptr;
  if (array->GetNumberOfComponents() != components || array->GetNumberOfTuples() != tuples) {
    throw InputError(std::string("array \"") + name + "\" has the wrong size", {what, "", ""});
  }
  return array;
}

/// Configures a VTK XML writer for byte-identical output: appended raw data, no compression.
template <typename Writer>
void write_deterministic(Writer& writer, const std::filesystem::path& path) {
  writer.SetFileName(path.string().c_str());
  writer.SetDataModeToAppended();
  writer.EncodeAppendedDataOff();
  writer.SetCompressorTypeToNone();
  writer.SetHeaderTypeToUInt64();
  if (writer.Write() != 1)
    throw OutputError("VTK could not write the file", {path.string(), "", ""});
}

template <typename Reader>
void read_checked(Reader& reader, const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError("file is missing", {path.string(), "", ""});
  reader.SetFileName(path.string().c_str());
  const ScopedVtkSilence silence;  // the failure is reported below, once, naming the file
  // VTK's XML readers crash on some damaged files (the package_folder fuzz target: a SEGV in
  // vtkXMLReader::ReadXMLInformation): the read runs first in a forked child.
  if (!survives_in_child([&] { reader.Update(); }))
    throw InputError(
        "the file is damaged: VTK's reader crashes, hangs or exhausts its memory on it",
        {path.string(), "", ""});
  reader.Update();
  if (reader.GetErrorCode() != 0 || reader.GetOutput() == nullptr) {
    throw InputError("not a readable VTK XML file", {path.string(), "", ""});
  }
}

}  // namespace

void surface_to_polydata(const SurfaceMesh& surface, const SurfaceEmbedding& embedding,
                         vtkPolyData& polydata) {
  const std::size_t n = surface.vertices.size();
  polydata.SetPoints(to_points(surface.vertices));
  vtkNew<vtkCellArray> triangles;
  for (const auto& t : surface.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    triangles->InsertNextCell(3, ids);
  }
  polydata.SetPolys(triangles);
  vtkPointData* data = polydata.GetPointData();
  if (!surface.normals.empty()) {
    auto normals = double_array("Normals", 3, n);
    for (std::size_t i = 0; i < n; ++i)
      normals->SetTuple(static_cast<vtkIdType>(i), surface.normals[i].data());
    data->SetNormals(normals);
  }
  if (!surface.uvs.empty()) {
    auto uvs = double_array("UV", 2, n);
    for (std::size_t i = 0; i < n; ++i)
      uvs->SetTuple(static_cast<vtkIdType>(i), surface.uvs[i].data());
    data->SetTCoords(uvs);
  }
  if (!embedding.empty()) {
    vtkNew<vtkIdTypeArray> tets;
    tets->SetName("embedding_tet");
    tets->SetNumberOfTuples(static_cast<vtkIdType>(n));
    auto weights = double_array("embedding_weights", 4, n);
    for (std::size_t i = 0; i < n; ++i) {
      tets->SetValue(static_cast<vtkIdType>(i), embedding.tet[i]);
      weights->SetTuple(static_cast<vtkIdType>(i), embedding.weights[i].data());
    }
    data->AddArray(tets);
    data->AddArray(weights);
  }
  for (const auto& [name, values] : surface.vertex_attributes) {
    auto array = double_array(name.c_str(), 1, n);
    for (std::size_t i = 0; i < n; ++i)
      array->SetValue(static_cast<vtkIdType>(i), values[i]);
    data->AddArray(array);
  }
}

void polydata_to_surface(vtkPolyData& polydata, const std::string& what, SurfaceMesh& surface,
                         SurfaceEmbedding& embedding) {
  surface = SurfaceMesh{};
  embedding = SurfaceEmbedding{};
  surface.vertices = from_points(polydata.GetPoints());
  const vtkIdType n = static_cast<vtkIdType>(surface.vertices.size());
  vtkCellArray* polys = polydata.GetPolys();
  if (polys != nullptr) {
    vtkNew<vtkIdList> ids;
    polys->InitTraversal();
    for (vtkIdType cell = 0; polys->GetNextCell(ids); ++cell) {
      if (ids->GetNumberOfIds() != 3) {
        throw InputError("polygon is not a triangle", {what, "", "cell " + std::to_string(cell)});
      }
      surface.triangles.push_back({static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
                                   static_cast<int>(ids->GetId(2))});
    }
  }
  vtkPointData* data = polydata.GetPointData();
  if (vtkDataArray* normals = checked_array(data, "Normals", 3, n, what)) {
    surface.normals.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      normals->GetTuple(i, surface.normals[i].data());
  }
  if (vtkDataArray* uvs = checked_array(data, "UV", 2, n, what)) {
    surface.uvs.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      uvs->GetTuple(i, surface.uvs[i].data());
  }
  vtkDataArray* tets = checked_array(data, "embedding_tet", 1, n, what);
  vtkDataArray* weights = checked_array(data, "embedding_weights", 4, n, what);
  if ((tets == nullptr) != (weights == nullptr)) {
    throw InputError("embedding needs both embedding_tet and embedding_weights", {what, "", ""});
  }
  if (tets != nullptr) {
    embedding.tet.resize(static_cast<std::size_t>(n));
    embedding.weights.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i) {
      embedding.tet[i] = index_in(*tets, i, 0, "embedding_tet", what);
      weights->GetTuple(i, embedding.weights[i].data());
    }
  }
  for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = data->GetArray(a);
    const std::string name = array && array->GetName() ? array->GetName() : "";
    if (name.empty() || name == "Normals" || name == "UV" || name == "embedding_tet" ||
        name == "embedding_weights") {
      continue;
    }
    if (array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != n) continue;
    auto& values = surface.vertex_attributes[name];
    values.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      values[i] = array->GetComponent(i, 0);
  }
  check_surface_mesh(surface, what);
}

void tet_mesh_to_grid(const TetMesh& body, vtkUnstructuredGrid& grid) {
  const std::size_t n = body.nodes.size();
  grid.SetPoints(to_points(body.nodes));
  grid.Allocate(static_cast<vtkIdType>(body.tets.size()));
  for (const auto& t : body.tets) {
    const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
    grid.InsertNextCell(VTK_TETRA, 4, ids);
  }
  if (!body.node_mass.empty()) {
    auto mass = double_array("node_mass", 1, n);
    for (std::size_t i = 0; i < n; ++i)
      mass->SetValue(static_cast<vtkIdType>(i), body.node_mass[i]);
    grid.GetPointData()->AddArray(mass);
  }
  if (!body.fixed.empty()) {
    vtkNew<vtkUnsignedCharArray> fixed;
    fixed->SetName("fixed");
    fixed->SetNumberOfTuples(static_cast<vtkIdType>(n));
    for (std::size_t i = 0; i < n; ++i)
      fixed->SetValue(static_cast<vtkIdType>(i), body.fixed[i]);
    grid.GetPointData()->AddArray(fixed);
  }
  if (!body.tet_labels.empty()) {
    vtkNew<vtkIntArray> labels;
    labels->SetName("tet_label");
    labels->SetNumberOfTuples(static_cast<vtkIdType>(body.tet_labels.size()));
    for (std::size_t i = 0; i < body.tet_labels.size(); ++i)
      labels->SetValue(static_cast<vtkIdType>(i), body.tet_labels[i]);
    grid.GetCellData()->AddArray(labels);
  }
  vtkNew<vtkIdTypeArray> faces;
  faces->SetName("surface_faces");
  faces->SetNumberOfComponents(3);
  faces->SetNumberOfTuples(static_cast<vtkIdType>(body.surface_faces.size()));
  for (std::size_t f = 0; f < body.surface_faces.size(); ++f) {
    for (int c = 0; c < 3; ++c)
      faces->SetComponent(static_cast<vtkIdType>(f), c, body.surface_faces[f][c]);
  }
  vtkNew<vtkFieldData> field;
  field->AddArray(faces);
  grid.SetFieldData(field);
}

TetMesh grid_to_tet_mesh(vtkUnstructuredGrid& grid, const std::string& what) {
  TetMesh body;
  body.nodes = from_points(grid.GetPoints());
  const vtkIdType n = static_cast<vtkIdType>(body.nodes.size());
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < grid.GetNumberOfCells(); ++cell) {
    if (grid.GetCellType(cell) != VTK_TETRA) {
      throw InputError("cell is not a tetrahedron", {what, "", "cell " + std::to_string(cell)});
    }
    grid.GetCellPoints(cell, ids);
    body.tets.push_back({static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
                         static_cast<int>(ids->GetId(2)), static_cast<int>(ids->GetId(3))});
  }
  if (vtkDataArray* mass = checked_array(grid.GetPointData(), "node_mass", 1, n, what)) {
    body.node_mass.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      body.node_mass[i] = mass->GetComponent(i, 0);
  }
  if (vtkDataArray* fixed = checked_array(grid.GetPointData(), "fixed", 1, n, what)) {
    body.fixed.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      body.fixed[i] = fixed->GetComponent(i, 0) != 0.0 ? 1 : 0;
  }
  if (vtkDataArray* labels =
          checked_array(grid.GetCellData(), "tet_label", 1, grid.GetNumberOfCells(), what)) {
    body.tet_labels.resize(static_cast<std::size_t>(grid.GetNumberOfCells()));
    for (vtkIdType i = 0; i < grid.GetNumberOfCells(); ++i)
      body.tet_labels[i] = static_cast<int>(labels->GetComponent(i, 0));
  }
  if (vtkFieldData* field = grid.GetFieldData()) {
    if (vtkDataArray* faces = field->GetArray("surface_faces")) {
      if (faces->GetNumberOfComponents() != 3) {
        throw InputError("array \"surface_faces\" needs 3 components", {what, "", ""});
      }
      body.surface_faces.resize(static_cast<std::size_t>(faces->GetNumberOfTuples()));
      for (vtkIdType f = 0; f < faces->GetNumberOfTuples(); ++f) {
        for (int c = 0; c < 3; ++c)
          body.surface_faces[f][c] = index_in(*faces, f, c, "surface_faces", what);
      }
    }
  }
  check_tet_mesh(body, what);
  return body;
}

void write_surface_vtp(const SurfaceMesh& surface, const SurfaceEmbedding& embedding,
                       const std::filesystem::path& path) {
  vtkNew<vtkPolyData> polydata;
  surface_to_polydata(surface, embedding, *polydata);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(polydata);
  write_deterministic(*writer, path);
}

void read_surface_vtp(const std::filesystem::path& path, SurfaceMesh& surface,
                      SurfaceEmbedding& embedding) {
  vtkNew<vtkXMLPolyDataReader> reader;
  read_checked(*reader, path);
  polydata_to_surface(*reader->GetOutput(), path.string(), surface, embedding);
}

void write_body_vtu(const TetMesh& body, const std::filesystem::path& path) {
  vtkNew<vtkUnstructuredGrid> grid;
  tet_mesh_to_grid(body, *grid);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  write_deterministic(*writer, path);
}

TetMesh read_body_vtu(const std::filesystem::path& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  read_checked(*reader, path);
  return grid_to_tet_mesh(*reader->GetOutput(), path.string());
}

}  // namespace viscera::core
