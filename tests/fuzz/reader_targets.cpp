/// Fuzz targets for the scan and mesh files a user opens (importers/): every volume format of
/// volume_reader.h, a DICOM folder, every surface format of mesh_reader.h and both tet formats.

#include "importers/mesh_reader.h"
#include "importers/volume/volume_reader.h"
#include "tests/fuzz/fuzz_target.h"

namespace viscera::fuzz {
namespace {

struct FileTarget {
  const char* name;
  const char* extension;
};

constexpr FileTarget kVolumeFiles[] = {
    {"volume_dicom_file", ".dcm"}, {"volume_nifti", ".nii"}, {"volume_nifti_gz", ".nii.gz"},
    {"volume_metaimage", ".mha"},  {"volume_nrrd", ".nrrd"}, {"volume_vti", ".vti"},
    {"volume_inr", ".inr"},        {"volume_minc", ".mnc"},
};

constexpr FileTarget kSurfaceFiles[] = {
    {"mesh_msh", ".msh"}, {"mesh_off", ".off"}, {"mesh_obj", ".obj"},
    {"mesh_stl", ".stl"}, {"mesh_ply", ".ply"}, {"mesh_gltf", ".gltf"},
    {"mesh_glb", ".glb"}, {"mesh_vtp", ".vtp"}, {"mesh_vtk", ".vtk"},
};

constexpr FileTarget kTetFiles[] = {{"tet_mesh_msh", ".msh"}, {"tet_mesh_vtu", ".vtu"}};

const bool registered = [] {
  for (const auto& file : kVolumeFiles) {
    register_target(file.name, [extension = std::string(file.extension)](Bytes bytes) {
      const auto path = input_file(bytes, extension);
      expect_typed_errors([&] { importers::read_volume(path); });
    });
  }
  // A folder of slices, some of them damaged: the input split at "\n--\n" into 0.dcm, 1.dcm, ….
  register_target("volume_dicom_folder", [](Bytes bytes) {
    const auto folder = input_folder(bytes, ".dcm");
    expect_typed_errors([&] { importers::read_volume(folder); });
  });
  for (const auto& file : kSurfaceFiles) {
    register_target(file.name, [extension = std::string(file.extension)](Bytes bytes) {
      const auto path = input_file(bytes, extension);
      expect_typed_errors([&] { importers::read_mesh(path); });
    });
  }
  for (const auto& file : kTetFiles) {
    register_target(file.name, [extension = std::string(file.extension)](Bytes bytes) {
      const auto path = input_file(bytes, extension);
      expect_typed_errors([&] { importers::read_tet_mesh(path); });
    });
  }
  return true;
}();

}  // namespace
}  // namespace viscera::fuzz
