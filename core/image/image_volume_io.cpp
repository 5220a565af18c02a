#include "core/image/image_volume_io.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkType.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>

#include <cstring>

#include "core/error.h"
#include "core/vtk_silence.h"

namespace viscera::core {
namespace {

int vtk_type_of(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
      return VTK_UNSIGNED_CHAR;
    case ScalarType::Int16:
      return VTK_SHORT;
    case ScalarType::UInt16:
      return VTK_UNSIGNED_SHORT;
    case ScalarType::Int32:
      return VTK_INT;
    case ScalarType::Float32:
      return VTK_FLOAT;
    case ScalarType::Float64:
      return VTK_DOUBLE;
  }
  return VTK_VOID;
}

bool scalar_type_of(int vtk_type, ScalarType& type) {
  for (const auto t : {ScalarType::UInt8, ScalarType::Int16, ScalarType::UInt16, ScalarType::Int32,
                       ScalarType::Float32, ScalarType::Float64}) {
    if (vtk_type_of(t) == vtk_type) {
      type = t;
      return true;
    }
  }
  return false;
}

void fill_image(const ImageVolume& volume, vtkImageData& image) {
  image.SetDimensions(volume.dims.data());
  image.SetSpacing(volume.spacing.data());
  image.SetOrigin(volume.origin.data());
  double direction[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      direction[3 * r + c] = volume.direction(r, c);
  image.SetDirectionMatrix(direction);
  image.AllocateScalars(vtk_type_of(volume.scalar_type), 1);
  if (!volume.voxels.empty()) {
    std::memcpy(image.GetScalarPointer(), volume.voxels.data(), volume.voxels.size());
  }
  image.GetPointData()->GetScalars()->SetName("scalars");
}

void write_image(vtkImageData& image, const std::filesystem::path& path) {
  const std::filesystem::path temporary = path.string() + ".partial";
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(&image);
  writer->SetFileName(temporary.string().c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToNone();
  writer->SetHeaderTypeToUInt64();
  if (writer->Write() != 1) {
    std::filesystem::remove(temporary);
    throw OutputError("VTK could not write the image", {path.string(), "", ""});
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace

void volume_to_image_data(const ImageVolume& volume, vtkImageData& image) {
  fill_image(volume, image);
}

void write_volume_vti(const ImageVolume& volume, const std::filesystem::path& path) {
  if (volume.voxels.size() != volume.voxel_count() * scalar_size(volume.scalar_type)) {
    throw OutputError("voxel buffer does not match the dimensions", {path.string(), "", ""});
  }
  vtkNew<vtkImageData> image;
  fill_image(volume, *image);
  write_image(*image, path);
}

ImageVolume read_volume_vti(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::is_regular_file(path)) throw InputError("no such file", {file, "", ""});
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(file.c_str());
  const ScopedVtkSilence silence;  // the failure is reported below, once, naming the file
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || image == nullptr ||
      image->GetPointData()->GetScalars() == nullptr) {
    throw InputError("not a readable VTK image file", {file, "", ""});
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (scalars->GetNumberOfComponents() != 1) {
    throw InputError("image has " + std::to_string(scalars->GetNumberOfComponents()) +
                         " components; one is needed",
                     {file, "", ""});
  }
  ImageVolume volume;
  if (!scalar_type_of(scalars->GetDataType(), volume.scalar_type)) {
    throw InputError(std::string("unsupported voxel type ") + scalars->GetDataTypeAsString(),
                     {file, "", ""});
  }
  image->GetDimensions(volume.dims.data());
  image->GetSpacing(volume.spacing.data());
  image->GetOrigin(volume.origin.data());
  const double* direction = image->GetDirectionMatrix()->GetData();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      volume.direction(r, c) = direction[3 * r + c];
  volume.allocate();
  if (static_cast<std::size_t>(scalars->GetNumberOfTuples()) != volume.voxel_count()) {
    throw InputError("voxel count does not match the dimensions", {file, "", ""});
  }
  std::memcpy(volume.voxels.data(), scalars->GetVoidPointer(0), volume.voxels.size());
  return volume;
}

void write_label_map_vti(const LabelMap& labels, const std::filesystem::path& path) {
  if (labels.image.scalar_type != ScalarType::UInt16) {
    throw OutputError("label maps hold unsigned 16-bit labels", {path.string(), "", ""});
  }
  vtkNew<vtkImageData> image;
  fill_image(labels.image, *image);
  vtkNew<vtkStringArray> names;
  names->SetName("label_names");
  for (const auto& [label, name] : labels.names)
    names->InsertNextValue(std::to_string(label) + "=" + name);
  vtkNew<vtkFieldData> field;
  field->AddArray(names);
  image->SetFieldData(field);
  write_image(*image, path);
}

LabelMap read_label_map_vti(const std::filesystem::path& path) {
  LabelMap labels;
  labels.image = read_volume_vti(path);
  if (labels.image.scalar_type != ScalarType::UInt16) {
    throw InputError("label map must hold unsigned 16-bit labels, found " +
                         scalar_type_name(labels.image.scalar_type),
                     {path.string(), "", ""});
  }
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  if (vtkFieldData* field = reader->GetOutput()->GetFieldData()) {
    if (auto* names = vtkStringArray::SafeDownCast(field->GetAbstractArray("label_names"))) {
      for (vtkIdType i = 0; i < names->GetNumberOfValues(); ++i) {
        const std::string entry = names->GetValue(i);
        const auto equals = entry.find('=');
        if (equals == std::string::npos) continue;
        labels.names[std::stoi(entry.substr(0, equals))] = entry.substr(equals + 1);
      }
    }
  }
  return labels;
}

}  // namespace viscera::core
