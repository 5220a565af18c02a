// VTK XML for ParaView. A .vtm names one block per object holding its surface (.vtp) and body
// (.vtu) pieces, written by core's package writers so they carry every array of the package
// (vtk_mesh_io.h) and the same mesh gives the same bytes.
#include "core/error.h"
#include "core/package/vtk_mesh_io.h"
#include "core/xml_text.h"
#include "exporters/format_writers.h"
#include "exporters/staged_output.h"

namespace viscera::exporters {
namespace {

void write_multiblock(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
                      const std::string& shown) {
  const std::string folder = main.stem().string();
  std::filesystem::create_directories(main.parent_path() / folder);
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <vtkMultiBlockDataSet>\n";
  for (std::size_t b = 0; b < objects.size(); ++b) {
    const ExportObject& object = objects[b];
    const std::string surface = folder + "/" + object.id() + "_surface.vtp";
    core::write_surface_vtp(object.surface, object.source->embedding, main.parent_path() / surface);
    xml += "    <Block index=\"" + std::to_string(b) + "\" name=\"" +
           core::xml_escaped(object.id()) + "\">\n";
    xml += "      <DataSet index=\"0\" name=\"surface\" file=\"" + core::xml_escaped(surface) +
           "\"/>\n";
    if (object.has_body()) {
      const std::string body = folder + "/" + object.id() + "_body.vtu";
      core::write_body_vtu(object.source->body, main.parent_path() / body);
      xml +=
          "      <DataSet index=\"1\" name=\"body\" file=\"" + core::xml_escaped(body) + "\"/>\n";
    }
    xml += "    </Block>\n";
  }
  xml += "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
  write_bytes(xml, main, shown);
}

}  // namespace

void write_vtk(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown) {
  const std::string extension = main.extension().string();
  if (extension == ".vtm") {
    write_multiblock(objects, main, shown);
    return;
  }
  if (objects.size() != 1) {
    throw core::UsageError("a " + extension +
                           " file holds one object; choose one with --object or write a .vtm");
  }
  const ExportObject& object = objects.front();
  if (extension == ".vtp") {
    core::write_surface_vtp(object.surface, object.source->embedding, main);
  } else {
    if (!object.has_body())
      throw core::UsageError("object \"" + object.id() +
                             "\" has no tetrahedral body to write as .vtu");
    core::write_body_vtu(object.source->body, main);
  }
}

}  // namespace viscera::exporters
