#include "exporters/volume/volume_writer.h"

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNIFTIImageWriter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkType.h>

#include <cstring>
#include <iomanip>
#include <sstream>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "exporters/staged_output.h"

namespace viscera::exporters {
namespace {

namespace fs = std::filesystem;

std::string lower_name(const fs::path& path) {
  std::string name = path.filename().string();
  for (auto& c : name)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int vtk_type_of(core::ScalarType type) {
  switch (type) {
    case core::ScalarType::UInt8:
      return VTK_UNSIGNED_CHAR;
    case core::ScalarType::Int16:
      return VTK_SHORT;
    case core::ScalarType::UInt16:
      return VTK_UNSIGNED_SHORT;
    case core::ScalarType::Int32:
      return VTK_INT;
    case core::ScalarType::Float32:
      return VTK_FLOAT;
    case core::ScalarType::Float64:
      return VTK_DOUBLE;
  }
  return VTK_VOID;
}

const char* meta_type_of(core::ScalarType type) {
  switch (type) {
    case core::ScalarType::UInt8:
      return "MET_UCHAR";
    case core::ScalarType::Int16:
      return "MET_SHORT";
    case core::ScalarType::UInt16:
      return "MET_USHORT";
    case core::ScalarType::Int32:
      return "MET_INT";
    case core::ScalarType::Float32:
      return "MET_FLOAT";
    case core::ScalarType::Float64:
      return "MET_DOUBLE";
  }
  return "MET_OTHER";
}

/// MetaImage with the voxels in the same file (ITK's conventions: LPS, mm; TransformMatrix
/// holds the direction of axis c as its c-th triple).
void write_mha(const core::ImageVolume& volume, const fs::path& path, const std::string& shown) {
  std::ostringstream header;
  header << std::setprecision(17);
  header << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
         << "CompressedData = False\nTransformMatrix =";
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      header << ' ' << volume.direction(r, c);
  header << "\nOffset = " << 1000 * volume.origin.x() << ' ' << 1000 * volume.origin.y() << ' '
         << 1000 * volume.origin.z() << "\nCenterOfRotation = 0 0 0\n"
         << "AnatomicalOrientation = LPS\nElementSpacing = " << 1000 * volume.spacing.x() << ' '
         << 1000 * volume.spacing.y() << ' ' << 1000 * volume.spacing.z()
         << "\nDimSize = " << volume.dims[0] << ' ' << volume.dims[1] << ' ' << volume.dims[2]
         << "\nElementType = " << meta_type_of(volume.scalar_type) << "\nElementDataFile = LOCAL\n";
  std::string bytes = header.str();
  bytes.append(reinterpret_cast<const char*>(volume.voxels.data()), volume.voxels.size());
  write_bytes(bytes, path, shown);
}

/// NIfTI-1 through VTK: the image goes in with spacing in mm and origin 0, the qform and sform
/// carry direction and origin converted from LPS to NIfTI's RAS.
void write_nifti(const core::ImageVolume& volume, const fs::path& path, const std::string& shown) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(volume.dims.data());
  image->SetSpacing(1000 * volume.spacing.x(), 1000 * volume.spacing.y(),
                    1000 * volume.spacing.z());
  image->AllocateScalars(vtk_type_of(volume.scalar_type), 1);
  std::memcpy(image->GetScalarPointer(), volume.voxels.data(), volume.voxels.size());
  vtkNew<vtkMatrix4x4> form;
  const core::Mat3 flip = core::Vec3(-1, -1, 1).asDiagonal();
  const core::Mat3 rotation = flip * volume.direction;
  const core::Vec3 origin = 1000 * (flip * volume.origin);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      form->SetElement(r, c, rotation(r, c));
    form->SetElement(r, 3, origin[r]);
  }
  vtkNew<vtkNIFTIImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.string().c_str());
  writer->SetQFormMatrix(form);
  writer->SetSFormMatrix(form);
  writer->Write();
  if (writer->GetErrorCode() != 0 || !fs::is_regular_file(path)) {
    throw core::OutputError("VTK could not write the NIfTI file", {shown, "", ""});
  }
}

}  // namespace

std::vector<std::string> volume_writer_extensions() {
  return {".vti", ".nii", ".nii.gz", ".mha"};
}

void write_volume(const core::ImageVolume& volume, const fs::path& path) {
  const std::string name = lower_name(path);
  const std::string shown = path.string();
  if (volume.voxels.size() != volume.voxel_count() * core::scalar_size(volume.scalar_type)) {
    throw core::OutputError("voxel buffer does not match the dimensions", {shown, "", ""});
  }
  const bool vti = ends_with(name, ".vti"), mha = ends_with(name, ".mha");
  const bool nifti = ends_with(name, ".nii") || ends_with(name, ".nii.gz");
  if (!vti && !mha && !nifti) {
    throw core::UsageError("\"" + shown +
                           "\": unknown volume format; use .vti, .nii, .nii.gz or .mha");
  }
  StagedOutput staged(path);
  if (vti) core::write_volume_vti(volume, staged.main_file());
  if (mha) write_mha(volume, staged.main_file(), shown);
  if (nifti) write_nifti(volume, staged.main_file(), shown);
  staged.commit();
}

}  // namespace viscera::exporters
