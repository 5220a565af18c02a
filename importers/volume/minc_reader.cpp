// MINC 1 (netCDF) through vtkMINCImageReader. World position of voxel (i, j, k) is
// Σ (start_a + index_a · step_a) · dircos_a over the xspace, yspace, zspace dimensions, in mm,
// in MINC's world frame (x towards the right, y anterior, z superior: RAS). Voxels are
// rescaled to real values with the file's image-min/image-max. MINC 2 files are HDF5, which
// VTK 9.1 does not read: they are refused by name.
#include <vtkImageData.h>
#include <vtkMINCImageReader.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <fstream>

#include "core/crash_guard.h"
#include "core/error.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/netcdf_header.h"
#include "importers/volume/volume_geometry.h"
#include "importers/vtk_error_capture.h"

namespace viscera::importers::detail {

LoadedVolume read_minc(const std::filesystem::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    if (std::string(magic + 1, 3) == "HDF") {
      throw core::InputError(
          "MINC 2 (HDF5) files cannot be read by VTK 9.1; convert to MINC 1 "
          "(mincconvert) or NIfTI",
          {file, "", ""});
    }
    if (std::string(magic, 3) != "CDF") {
      throw core::InputError("not a MINC 1 file (no netCDF CDF magic)", {file, "", ""});
    }
  }
  // The netCDF library allocates what the header declares before it checks it against the file.
  check_netcdf_header(path);
  vtkNew<vtkMINCImageReader> reader;
  reader->SetFileName(file.c_str());
  reader->RescaleRealValuesOn();
  const std::uint64_t declared = check_reader_budget(*reader, options, file);
  // VTK's MINC reader can also crash reading the voxels of a damaged file (volume_minc fuzz
  // target, a SEGV in ExecuteDataWithInformation): the whole read runs first in a forked child.
  if (!core::survives_in_child([&] { reader->Update(); }, core::guard_memory_for(declared)))
    throw core::InputError(
        "the file is damaged: VTK's MINC reader crashes, hangs or exhausts its memory on it",
        {file, "", ""});
  std::string error;
  {
    VtkErrorCapture capture;
    reader->Update();
    error = capture.first_error();
  }
  if (!error.empty()) throw core::InputError("cannot read the voxels: " + error, {file, "", ""});

  LoadedVolume loaded;
  loaded.format = "MINC";
  loaded.files = {path};
  vtkImageData* image = reader->GetOutput();
  loaded.volume = volume_from_vtk_image(*image, file, loaded.notes);
  if (reader->GetNumberOfTimeSteps() > 1) {
    loaded.notes.push_back("first of " + std::to_string(reader->GetNumberOfTimeSteps()) +
                           " time points read");
  }
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  core::Mat3 cosines = core::Mat3::Identity();
  if (vtkMatrix4x4* matrix = reader->GetDirectionCosines()) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        cosines(r, c) = matrix->GetElement(r, c);
  }
  const core::Vec3 step(spacing[0], spacing[1], spacing[2]);
  set_geometry_mm(loaded.volume, cosines * step.asDiagonal(),
                  cosines * core::Vec3(origin[0], origin[1], origin[2]), true, file);
  return loaded;
}

}  // namespace viscera::importers::detail
