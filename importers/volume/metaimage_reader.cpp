// MetaImage (.mha with its voxels inside, .mhd beside a raw file) through vtkMetaImageReader.
// VTK 9.1's reader keeps ElementSpacing and Offset but drops TransformMatrix, so the
// direction is read from the header text here. MetaImage coordinates are ITK's: LPS, mm.
#include <vtkImageData.h>
#include <vtkMetaImageReader.h>
#include <vtkNew.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/image_read_in_child.h"
#include "importers/volume/volume_geometry.h"
#include "importers/vtk_error_capture.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

struct MetaHeader {
  std::vector<double> transform;  ///< TransformMatrix (also Rotation, Orientation), row-major
  std::string data_file;          ///< ElementDataFile
};

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

/// The "Key = value" lines up to ElementDataFile (the last header line).
MetaHeader read_header(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  MetaHeader header;
  std::string line;
  for (int lines = 0; lines < 200 && std::getline(in, line); ++lines) {
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue;
    const std::string key = trim(line.substr(0, equals));
    const std::string value = trim(line.substr(equals + 1));
    if (key == "TransformMatrix" || key == "Rotation" || key == "Orientation") {
      std::istringstream numbers(value);
      header.transform.clear();
      for (double v; numbers >> v;)
        header.transform.push_back(v);
    } else if (key == "ElementDataFile") {
      header.data_file = value;
      break;
    }
  }
  return header;
}

}  // namespace

LoadedVolume read_metaimage(const fs::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  const MetaHeader header = read_header(path);
  if (header.data_file.empty()) {
    throw core::InputError("MetaImage header has no ElementDataFile line", {file, "", ""});
  }
  LoadedVolume loaded;
  loaded.format = "MetaImage";
  loaded.files = {path};
  if (header.data_file != "LOCAL" && header.data_file.rfind("LIST", 0) != 0 &&
      header.data_file.find('%') == std::string::npos) {
    const fs::path data = path.parent_path() / header.data_file;
    if (!fs::is_regular_file(data)) {
      throw core::InputError(
          "the voxel file " + header.data_file + " named by the header is missing", {file, "", ""});
    }
    loaded.files.push_back(data);
  }

  vtkNew<vtkMetaImageReader> reader;
  reader->SetFileName(file.c_str());
  // vtkmetaio divides by zero on some damaged headers (volume_metaimage fuzz target: an FPE in
  // MetaImage::ReadStream) and corrupts the heap on others without crashing at once (the same
  // target, later): the read runs only in a child, which sends the voxels back.
  const vtkSmartPointer<vtkImageData> read = read_image_in_child(
      [&]() -> vtkImageData* {
        check_reader_budget(*reader, options, file);  // the header is vtkmetaio's too
        VtkErrorCapture capture;
        reader->Update();
        if (const std::string error = capture.first_error(); !error.empty())
          throw core::InputError("cannot read the voxels: " + error);
        return reader->GetOutput();
      },
      file, "VTK's MetaImage reader", core::guard_memory_for(options.max_bytes));
  vtkImageData* image = read.Get();
  loaded.volume = volume_from_vtk_image(*image, file, loaded.notes);
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  core::Mat3 direction = core::Mat3::Identity();
  if (header.transform.size() == 9) {
    // ITK writes axis c of the direction as the c-th triple of TransformMatrix.
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        direction(r, c) = header.transform[3 * c + r];
  } else if (!header.transform.empty()) {
    loaded.notes.push_back("TransformMatrix is not 3×3; axes taken as aligned with the world");
  }
  const core::Vec3 step(spacing[0], spacing[1], spacing[2]);
  set_geometry_mm(loaded.volume, direction * step.asDiagonal(),
                  core::Vec3(origin[0], origin[1], origin[2]), false, file);
  return loaded;
}

}  // namespace viscera::importers::detail
