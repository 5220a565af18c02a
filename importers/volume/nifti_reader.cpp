// NIfTI-1/-2 and Analyze 7.5 through vtkNIFTIImageReader. Geometry from the header as
// nibabel's get_best_affine() chooses it: the sform if sform_code > 0, else the qform if
// qform_code > 0, else the pixdim diagonal. VTK hands both matrices over with the pixel
// spacing factored out and the slices reversed when qfac = -1; the affine is rebuilt from
// them, so every voxel keeps its world position.
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>

#include "core/error.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/image_read_in_child.h"
#include "importers/volume/nifti_header.h"
#include "importers/volume/volume_geometry.h"
#include "importers/vtk_error_capture.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

bool is_gzip(const fs::path& path) {
  const std::string name = path.filename().string();
  return name.size() > 3 && name.compare(name.size() - 3, 3, ".gz") == 0;
}

/// The file holding the voxels: the .nii itself, or the .img beside a .hdr.
fs::path voxel_file(const fs::path& path) {
  std::string name = path.string();
  const auto swap_suffix = [&](const std::string& from, const std::string& to) {
    if (name.size() >= from.size() &&
        name.compare(name.size() - from.size(), from.size(), from) == 0) {
      name = name.substr(0, name.size() - from.size()) + to;
      return true;
    }
    return false;
  };
  if (swap_suffix(".hdr", ".img") || swap_suffix(".HDR", ".IMG")) return name;
  return path;
}

/// Millimetres per unit of the header's xyzt_units (NIfTI-1: 1 m, 2 mm, 3 µm; 0 unknown).
double millimetres_per_unit(int xyzt_units, std::vector<std::string>& notes) {
  switch (xyzt_units & 7) {
    case 1:
      return 1000.0;
    case 2:
      return 1.0;
    case 3:
      return 0.001;
    default:
      notes.push_back("header gives no spatial unit; millimetres assumed");
      return 1.0;
  }
}

}  // namespace

LoadedVolume read_nifti(const fs::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  check_nifti_header(path);  // VTK's own check of these fields is not repeatable
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(file.c_str());
  const std::uint64_t declared = check_reader_budget(*reader, options, file);
  vtkNIFTIImageHeader* header = reader->GetNIFTIHeader();
  if (header == nullptr) throw core::InputError("not a NIfTI or Analyze header", {file, "", ""});

  // An uncompressed file shorter than its header says is refused before VTK reads past its end.
  const fs::path voxels = voxel_file(path);
  if (!fs::is_regular_file(voxels)) {
    throw core::InputError(
        "the voxel file " + voxels.filename().string() + " beside the header is missing",
        {file, "", ""});
  }
  if (!is_gzip(voxels)) {
    long double needed = header->GetBitPix() / 8.0L;
    for (int d = 1; d <= std::max<vtkTypeInt64>(1, std::min<vtkTypeInt64>(header->GetDim(0), 7));
         ++d) {
      needed *= std::max<vtkTypeInt64>(1, header->GetDim(d));
    }
    // Only the first volume of a time series is read; it must be there in full.
    if (header->GetDim(0) > 3) needed /= std::max<vtkTypeInt64>(1, header->GetDim(4));
    const long double offset =
        voxels == path ? static_cast<long double>(header->GetVoxOffset()) : 0.0L;
    const auto size = fs::file_size(voxels);
    if (offset + needed > static_cast<long double>(size)) {
      throw core::InputError("file is truncated: the header asks for " +
                                 std::to_string(static_cast<unsigned long long>(offset + needed)) +
                                 " bytes, the file has " + std::to_string(size),
                             {voxels.string(), "", ""});
    }
  }

  // VTK 9.1's NIfTI reader can also crash reading the voxels of a damaged file (volume_nifti
  // fuzz target), or take gigabytes for a few hundred bytes of header (the same target, later):
  // the voxels are read only in a child, bounded by the size the header declares, which sends
  // them back. The header (and the qform and sform VTK derived from it) is this process's.
  const vtkSmartPointer<vtkImageData> read = read_image_in_child(
      [&]() -> vtkImageData* {
        VtkErrorCapture capture;
        reader->Update();
        if (const std::string error = capture.first_error(); !error.empty())
          throw core::InputError("cannot read the voxels: " + error);
        return reader->GetOutput();
      },
      file, "VTK's NIfTI reader", core::guard_memory_for(declared));

  LoadedVolume loaded;
  loaded.format = header->GetMagic()[0] == '\0' ? "Analyze 7.5" : "NIfTI";
  loaded.files = {path};
  if (voxels != path) loaded.files.push_back(voxels);
  vtkImageData* image = read.Get();
  loaded.volume = volume_from_vtk_image(*image, file, loaded.notes);
  if (header->GetDim(0) > 3 && header->GetDim(4) > 1) {
    loaded.notes.push_back("first of " + std::to_string(header->GetDim(4)) + " time points read");
  }

  const double unit = millimetres_per_unit(header->GetXYZTUnits(), loaded.notes);
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  vtkMatrix4x4* form = nullptr;
  if (header->GetSFormCode() > 0) form = reader->GetSFormMatrix();
  if (form == nullptr && header->GetQFormCode() > 0) form = reader->GetQFormMatrix();
  core::Mat3 rotation = core::Mat3::Identity();
  core::Vec3 translation = core::Vec3::Zero();
  if (form != nullptr) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        rotation(r, c) = form->GetElement(r, c);
      translation[r] = form->GetElement(r, 3);
    }
  } else {
    loaded.notes.push_back("header has no qform or sform; axes taken as aligned with the world");
  }
  const core::Vec3 step(spacing[0], spacing[1], spacing[2]);
  const core::Mat3 axes = unit * rotation * step.asDiagonal();
  const core::Vec3 world_origin =
      unit * (rotation * core::Vec3(origin[0], origin[1], origin[2]) + translation);
  set_geometry_mm(loaded.volume, axes, world_origin, form != nullptr, file);
  apply_rescale(loaded.volume, header->GetSclSlope(), header->GetSclInter());
  return loaded;
}

}  // namespace viscera::importers::detail
