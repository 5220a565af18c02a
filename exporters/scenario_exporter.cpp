#include "exporters/scenario_exporter.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "core/package/zip_archive.h"
#include "exporters/export_object.h"
#include "exporters/format_writers.h"
#include "exporters/staged_output.h"

namespace viscera::exporters {
namespace {

struct FormatEntry {
  ExportFormat format;
  const char* name;
  std::vector<std::string> extensions;  ///< the first is the usual one
};

const std::vector<FormatEntry>& format_table() {
  static const std::vector<FormatEntry> table = {
      {ExportFormat::Vtk, "vtk", {".vtm", ".vtp", ".vtu"}},
      {ExportFormat::Gltf, "gltf", {".gltf"}},
      {ExportFormat::Glb, "glb", {".glb"}},
      {ExportFormat::Obj, "obj", {".obj"}},
      {ExportFormat::Stl, "stl", {".stl"}},
      {ExportFormat::Ply, "ply", {".ply"}},
      {ExportFormat::Msh, "msh", {".msh"}},
      {ExportFormat::Sofa, "sofa", {".scn"}},
  };
  return table;
}

const FormatEntry& entry_of(ExportFormat format) {
  const auto& table = format_table();
  return *std::find_if(table.begin(), table.end(),
                       [&](const FormatEntry& e) { return e.format == format; });
}

void write_format(const core::Scenario& scenario, const std::vector<ExportObject>& objects,
                  ExportFormat format, const std::filesystem::path& main,
                  const std::string& shown) {
  switch (format) {
    case ExportFormat::Vtk:
      return write_vtk(objects, main, shown);
    case ExportFormat::Gltf:
      return write_gltf(objects, false, main, shown);
    case ExportFormat::Glb:
      return write_gltf(objects, true, main, shown);
    case ExportFormat::Obj:
      return write_obj(objects, main, shown);
    case ExportFormat::Stl:
      return write_stl(objects, main, shown);
    case ExportFormat::Ply:
      return write_ply(objects, main, shown);
    case ExportFormat::Msh:
      return write_msh(objects, main, shown);
    case ExportFormat::Sofa:
      return write_sofa(scenario, objects, main, shown);
  }
}

std::string read_whole_file(const std::filesystem::path& path, const std::string& shown) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw core::InputError("texture map is missing from the package", {shown, "", ""});
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace

ExportFormat export_format_from_string(const std::string& name) {
  std::string names;
  for (const auto& e : format_table()) {
    if (name == e.name) return e.format;
    names += (names.empty() ? "" : ", ") + std::string(e.name);
  }
  throw core::UsageError("unknown export format \"" + name + "\"; use one of " + names);
}

std::string to_string(ExportFormat format) {
  return entry_of(format).name;
}

const std::vector<ExportFormat>& export_formats() {
  static const std::vector<ExportFormat> formats = [] {
    std::vector<ExportFormat> list;
    for (const auto& e : format_table())
      list.push_back(e.format);
    return list;
  }();
  return formats;
}

ExportReport export_scenario(const core::Scenario& scenario, ExportFormat format,
                             const std::filesystem::path& out, const TextureFiles& textures,
                             const ExportOptions& options, core::Progress& progress) {
  const FormatEntry& entry = entry_of(format);
  const std::string extension = out.extension().string();
  if (std::find(entry.extensions.begin(), entry.extensions.end(), extension) ==
      entry.extensions.end()) {
    std::string allowed;
    for (const auto& e : entry.extensions)
      allowed += (allowed.empty() ? "" : " or ") + e;
    throw core::UsageError("the output of --format " + std::string(entry.name) + " must end in " +
                           allowed + ": \"" + out.string() + "\"");
  }
  ExportReport report;
  progress.begin_stage("preparing objects", 1);
  const std::vector<ExportObject> objects =
      gather_export_objects(scenario, textures, options, report.sanitized_values);
  progress.step();
  const std::string shown = out.string();
  StagedOutput staged(out);
  try {
    progress.begin_stage("writing " + std::string(entry.name), 1);
    write_format(scenario, objects, format, staged.main_file(), shown);
  } catch (const core::Error&) {
    throw;
  } catch (const std::exception& e) {
    throw core::OutputError(std::string("cannot write the export: ") + e.what(), {shown, "", ""});
  }
  progress.step();
  report.files = staged.commit();
  report.objects = static_cast<int>(objects.size());
  for (const auto& object : objects) {
    report.triangles += object.surface.triangles.size();
    if (object.has_body()) report.tets += object.source->body.tets.size();
  }
  return report;
}

TextureFiles read_package_textures(const std::filesystem::path& package,
                                   const core::Scenario& scenario) {
  TextureFiles files;
  const bool folder = std::filesystem::is_directory(package);
  const core::ZipLimits limits{core::kMaxZipEntryBytes, core::kMaxPackageBytes};
  for (const auto& [id, texture] : scenario.textures) {
    for (const auto& [map, path] : texture.maps) {
      if (files.contains(path)) continue;
      const std::string shown = package.string() + "/" + path;
      files[path] = folder ? read_whole_file(package / path, shown)
                           : core::read_zip_entry(package, path, limits);
    }
  }
  return files;
}

}  // namespace viscera::exporters
