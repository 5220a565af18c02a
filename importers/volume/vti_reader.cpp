// VTK XML image data (.vti) as Viscera writes it (core/image/image_volume_io.h): origin,
// spacing and direction matrix are already in metres, so nothing is converted. The extent is
// checked against the memory limit from the XML header before the voxels are read.
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLImageDataReader.h>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/volume_geometry.h"
#include "importers/vtk_error_capture.h"

namespace viscera::importers::detail {

LoadedVolume read_vti(const std::filesystem::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(file.c_str());
  std::string error;
  {
    VtkErrorCapture capture;
    reader->UpdateInformation();
    error = capture.first_error();
  }
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!error.empty() || info == nullptr ||
      !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT())) {
    throw core::InputError("not a readable VTK image file" + (error.empty() ? "" : ": " + error),
                           {file, "", ""});
  }
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  check_voxel_budget(
      {std::int64_t{extent[1]} - extent[0] + 1, std::int64_t{extent[3]} - extent[2] + 1,
       std::int64_t{extent[5]} - extent[4] + 1},
      vtkImageData::GetNumberOfScalarComponents(info),
      vtkDataArray::GetDataTypeSize(vtkImageData::GetScalarType(info)), options, file);
  LoadedVolume loaded;
  loaded.format = "VTK image";
  loaded.files = {path};
  {
    VtkErrorCapture capture;  // core::read_volume_vti reports its own failure
    loaded.volume = core::read_volume_vti(path);
  }
  if (loaded.volume.voxel_count() == 0)
    throw core::InputError("file holds no voxels", {file, "", ""});
  return loaded;
}

}  // namespace viscera::importers::detail
