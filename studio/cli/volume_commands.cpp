#include "studio/cli/volume_commands.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <sstream>

#include "exporters/volume/volume_writer.h"
#include "importers/volume/volume_reader.h"
#include "studio/cli/command_output.h"

namespace viscera::cli {
namespace {

struct VolumeOptions {
  std::string input, output;
  bool json = false;
  std::uint64_t max_memory_mib = 4096;
};

importers::VolumeReadOptions read_options(const VolumeOptions& o) {
  importers::VolumeReadOptions options;
  options.max_bytes = o.max_memory_mib * 1024 * 1024;
  return options;
}

nlohmann::json vec_json(const core::Vec3& v, double scale) {
  return {scale * v.x(), scale * v.y(), scale * v.z()};
}

/// The JSON description of a loaded volume (lengths in mm, patient LPS).
nlohmann::json describe(const importers::LoadedVolume& loaded, const std::string& input) {
  const core::ImageVolume& v = loaded.volume;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < v.voxel_count(); ++i) {
    const double value = v.value(i);
    lo = std::min(lo, value);
    hi = std::max(hi, value);
  }
  nlohmann::json direction = nlohmann::json::array();
  for (int r = 0; r < 3; ++r)
    direction.push_back(vec_json(v.direction.row(r).transpose(), 1.0));
  nlohmann::json others = nlohmann::json::array();
  for (const auto& s : loaded.other_series) {
    others.push_back({{"uid", s.uid},
                      {"description", s.description},
                      {"modality", s.modality},
                      {"files", s.files}});
  }
  nlohmann::json skipped = nlohmann::json::array();
  for (const auto& s : loaded.skipped_files)
    skipped.push_back({{"file", s.file.string()}, {"reason", s.reason}});
  return {{"input", std::filesystem::absolute(input).lexically_normal().string()},
          {"format", loaded.format},
          {"files", loaded.files.size()},
          {"dims", {v.dims[0], v.dims[1], v.dims[2]}},
          {"spacing_mm", vec_json(v.spacing, 1000.0)},
          {"origin_mm", vec_json(v.origin, 1000.0)},
          {"direction", direction},
          {"scalar_type", core::scalar_type_name(v.scalar_type)},
          {"value_range", {lo, hi}},
          {"notes", loaded.notes},
          {"other_series", others},
          {"skipped_files", skipped}};
}

std::string text_of(const nlohmann::json& info) {
  std::ostringstream out;
  const auto triple = [](const nlohmann::json& a) {
    std::ostringstream t;
    t << a[0].get<double>() << " " << a[1].get<double>() << " " << a[2].get<double>();
    return t.str();
  };
  out << info["input"].get<std::string>() << "\n"
      << "  format        " << info["format"].get<std::string>() << " (" << info["files"]
      << " files)\n"
      << "  dims          " << info["dims"][0] << " × " << info["dims"][1] << " × "
      << info["dims"][2] << "\n"
      << "  spacing mm    " << triple(info["spacing_mm"]) << "\n"
      << "  origin mm     " << triple(info["origin_mm"]) << "  (patient LPS)\n"
      << "  direction     " << triple(info["direction"][0]) << " | " << triple(info["direction"][1])
      << " | " << triple(info["direction"][2]) << "  (rows)\n"
      << "  scalar type   " << info["scalar_type"].get<std::string>() << "\n"
      << "  value range   " << info["value_range"][0].get<double>() << " … "
      << info["value_range"][1].get<double>() << "\n";
  for (const auto& note : info["notes"])
    out << "  note          " << note.get<std::string>() << "\n";
  for (const auto& s : info["other_series"]) {
    out << "  other series  " << s["uid"].get<std::string>() << " "
        << s["modality"].get<std::string>() << " \"" << s["description"].get<std::string>()
        << "\" (" << s["files"] << " files)\n";
  }
  for (const auto& s : info["skipped_files"]) {
    out << "  skipped       " << s["file"].get<std::string>() << ": "
        << s["reason"].get<std::string>() << "\n";
  }
  return out.str();
}

void info(const VolumeOptions& o) {
  const auto loaded = importers::read_volume(o.input, read_options(o));
  const auto json = describe(loaded, o.input);
  if (o.json)
    print_json(json);
  else
    print_text(text_of(json));
}

void convert(const VolumeOptions& o) {
  const auto loaded = importers::read_volume(o.input, read_options(o));
  exporters::write_volume(loaded.volume, o.output);
  const std::string output = std::filesystem::absolute(o.output).lexically_normal().string();
  if (o.json) {
    auto json = describe(loaded, o.input);
    json["output"] = output;
    print_json(json);
  } else {
    print_text("wrote " + output + "\n");
  }
}

void add_common(CLI::App& command, VolumeOptions& o) {
  command
      .add_option(
          "input", o.input,
          "Volume file or DICOM folder (DICOM, NIfTI, MetaImage, NRRD, .vti, INRIMAGE, MINC 1)")
      ->required();
  command.add_flag("--json", o.json, "Print JSON");
  command.add_option("--max-memory", o.max_memory_mib, "Largest voxel buffer to allocate, MiB")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

}  // namespace

void add_volume_commands(CLI::App& app) {
  auto* volume = app.add_subcommand("volume", "Image volume inspection and conversion");
  volume->require_subcommand(1);

  auto info_options = std::make_shared<VolumeOptions>();
  auto* info_command = volume->add_subcommand("info", "Print a volume's geometry and values");
  add_common(*info_command, *info_options);
  info_command->callback([info_options] { info(*info_options); });

  auto convert_options = std::make_shared<VolumeOptions>();
  auto* convert_command = volume->add_subcommand(
      "convert", "Convert a volume; format by extension (.vti .nii .nii.gz .mha)");
  add_common(*convert_command, *convert_options);
  convert_command
      ->add_option("-o,--output", convert_options->output, "Output volume (.vti .nii .nii.gz .mha)")
      ->required();
  convert_command->callback([convert_options] { convert(*convert_options); });
}

}  // namespace viscera::cli
