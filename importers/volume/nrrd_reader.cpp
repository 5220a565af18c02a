// NRRD (.nrrd, or .nhdr beside its data) through vtkNrrdReader for the voxels. VTK 9.1 keeps
// only the lengths of "space directions", so the geometry is read from the header text here:
// space directions (the world step of each axis), space origin, and the space they are in
// (RAS and LPS spellings of the NRRD format, 3D spaces only).
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkNrrdReader.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/volume_geometry.h"
#include "importers/vtk_error_capture.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

struct NrrdHeader {
  std::string space;
  std::vector<core::Vec3> directions;  ///< one per spatial axis, in the file's space units
  core::Vec3 origin = core::Vec3::Zero();
  std::vector<double> spacings;
};

/// The vectors "(a,b,c)" of a field value; "none" entries (non-spatial axes) are skipped.
std::vector<core::Vec3> vectors_of(const std::string& value) {
  static const std::regex vector(R"(\(\s*([^,\)]+),\s*([^,\)]+),\s*([^,\)]+)\))");
  std::vector<core::Vec3> result;
  for (auto it = std::sregex_iterator(value.begin(), value.end(), vector);
       it != std::sregex_iterator(); ++it) {
    result.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]));
  }
  return result;
}

NrrdHeader read_header(const fs::path& path, const std::string& file) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("NRRD000", 0) != 0) {
    throw core::InputError("not a NRRD file (no NRRD000x magic line)", {file, "", ""});
  }
  NrrdHeader header;
  for (int lines = 0; lines < 500 && std::getline(in, line); ++lines) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) break;  // the blank line before the data
    if (line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon == std::string::npos) continue;
    const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
    try {
      if (key == "space") {
        header.space = value;
      } else if (key == "space directions") {
        header.directions = vectors_of(value);
      } else if (key == "space origin") {
        const auto origin = vectors_of(value);
        if (origin.size() == 1) header.origin = origin[0];
      } else if (key == "spacings") {
        std::istringstream numbers(value);
        for (std::string word; numbers >> word;)
          header.spacings.push_back(std::stod(word));
      }
    } catch (const std::exception&) {
      throw core::InputError("header field \"" + key + "\" holds a number that cannot be read",
                             {file, "", ""});
    }
  }
  return header;
}

}  // namespace

LoadedVolume read_nrrd(const fs::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  const NrrdHeader header = read_header(path, file);
  vtkNew<vtkNrrdReader> reader;
  reader->SetFileName(file.c_str());
  check_reader_budget(*reader, options, file);
  std::string error;
  {
    VtkErrorCapture capture;
    reader->Update();
    error = capture.first_error();
  }
  if (!error.empty()) throw core::InputError("cannot read the voxels: " + error, {file, "", ""});

  LoadedVolume loaded;
  loaded.format = "NRRD";
  loaded.files = {path};
  vtkImageData* image = reader->GetOutput();
  loaded.volume = volume_from_vtk_image(*image, file, loaded.notes);
  core::Mat3 axes = core::Mat3::Identity();
  bool ras = false;
  if (header.directions.size() == 3) {
    for (int c = 0; c < 3; ++c)
      axes.col(c) = header.directions[c];
    const std::string& s = header.space;
    ras = s == "right-anterior-superior" || s == "RAS" || s == "scanner-xyz";
    if (!ras && s != "left-posterior-superior" && s != "LPS") {
      loaded.notes.push_back("space \"" + s + "\" taken as LPS");
    }
  } else {
    double spacing[3];
    image->GetSpacing(spacing);
    axes = core::Vec3(spacing[0], spacing[1], spacing[2]).asDiagonal();
    loaded.notes.push_back(
        "header has no 3D space directions; axes taken as aligned with the world");
  }
  set_geometry_mm(loaded.volume, axes, header.origin, ras, file);
  return loaded;
}

}  // namespace viscera::importers::detail
