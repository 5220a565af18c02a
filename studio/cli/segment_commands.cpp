#include "studio/cli/segment_commands.h"

#include <filesystem>
#include <limits>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "core/segmentation/label_operations.h"
#include "core/segmentation/morphology.h"
#include "core/segmentation/region_growing.h"
#include "core/segmentation/threshold.h"
#include "exporters/staged_output.h"
#include "importers/volume/volume_reader.h"
#include "studio/cli/command_output.h"

namespace viscera::cli {
namespace {

struct SegmentOptions {
  std::string input, output;
  std::vector<std::string> thresholds, grows, merges, relabels, names;
  std::vector<int> removes;
  int open = 0, close = 0;
  bool largest = false, json = false;
  std::uint64_t max_memory_mib = 4096;
};

const std::string kNumber = R"(([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?))";

std::uint16_t label_of(const std::string& text, const std::string& option) {
  const long value = std::stol(text);
  if (value < 0 || value > 65535) {
    throw core::UsageError(option + ": label " + text + " is outside 0…65535");
  }
  return static_cast<std::uint16_t>(value);
}

std::vector<core::ThresholdBand> parse_thresholds(const std::vector<std::string>& specs) {
  static const std::regex pattern("^" + kNumber + ":" + kNumber + R"((?:=(\d+))?$)");
  std::vector<core::ThresholdBand> bands;
  for (const auto& spec : specs) {
    std::smatch m;
    if (!std::regex_match(spec, m, pattern)) {
      throw core::UsageError("--threshold " + spec + ": expected LO:HI or LO:HI=LABEL");
    }
    bands.push_back({std::stod(m[1]), std::stod(m[2]),
                     m[3].matched ? label_of(m[3], "--threshold") : std::uint16_t{1}});
  }
  return bands;
}

struct Grow {
  core::Vec3 point_m;
  double tolerance = 0.0;
  std::uint16_t label = 1;
};

std::vector<Grow> parse_grows(const std::vector<std::string>& specs) {
  static const std::regex pattern("^" + kNumber + "," + kNumber + "," + kNumber + "(?::" + kNumber +
                                  R"()?(?:=(\d+))?$)");
  std::vector<Grow> grows;
  for (const auto& spec : specs) {
    std::smatch m;
    if (!std::regex_match(spec, m, pattern)) {
      throw core::UsageError("--grow " + spec + ": expected X,Y,Z[:TOL][=LABEL] with X,Y,Z in mm");
    }
    grows.push_back({0.001 * core::Vec3(std::stod(m[1]), std::stod(m[2]), std::stod(m[3])),
                     m[4].matched ? std::stod(m[4]) : 0.0,
                     m[5].matched ? label_of(m[5], "--grow") : std::uint16_t{1}});
  }
  return grows;
}

/// Draws the non-zero labels of `layer` over `labels`.
void draw_over(core::LabelMap& labels, const core::LabelMap& layer) {
  for (std::size_t v = 0; v < labels.image.voxel_count(); ++v)
    if (const auto label = layer.label(v); label != 0) labels.set_label(v, label);
}

void segment(const SegmentOptions& o) {
  if (o.thresholds.empty() && o.grows.empty()) {
    throw core::UsageError("segment needs at least one --threshold or --grow");
  }
  if (std::filesystem::path(o.output).extension() != ".vti") {
    throw core::UsageError("\"" + o.output + "\": label maps are written as .vti");
  }
  const auto bands = parse_thresholds(o.thresholds);
  const auto grows = parse_grows(o.grows);
  importers::VolumeReadOptions read;
  read.max_bytes = o.max_memory_mib * 1024 * 1024;
  const auto loaded = importers::read_volume(o.input, read);
  const core::ImageVolume& volume = loaded.volume;

  core::LabelMap labels =
      bands.empty() ? core::empty_label_map(volume) : core::multi_threshold(volume, bands);
  for (const auto& grow : grows) {
    draw_over(labels, core::grow_region(volume, core::voxel_at(volume, grow.point_m),
                                        grow.tolerance, grow.label));
  }
  if (o.open > 0) labels = core::open_labels(labels, o.open);
  if (o.close > 0) labels = core::close_labels(labels, o.close);
  if (o.largest) labels = core::keep_largest_component(labels);
  for (const auto& spec : o.merges) {
    static const std::regex pattern(R"(^(\d+(?:,\d+)*)=(\d+)$)");
    std::smatch m;
    if (!std::regex_match(spec, m, pattern))
      throw core::UsageError("--merge " + spec + ": expected A,B,…=C");
    std::vector<std::uint16_t> from;
    std::istringstream list(m[1].str());
    for (std::string part; std::getline(list, part, ',');)
      from.push_back(label_of(part, "--merge"));
    labels = core::merge_labels(labels, from, label_of(m[2], "--merge"));
  }
  for (const int label : o.removes)
    labels = core::remove_label(labels, label_of(std::to_string(label), "--remove"));
  for (const auto& spec : o.relabels) {
    static const std::regex pattern(R"(^(\d+)=(\d+)$)");
    std::smatch m;
    if (!std::regex_match(spec, m, pattern))
      throw core::UsageError("--relabel " + spec + ": expected A=B");
    labels = core::relabel(labels, label_of(m[1], "--relabel"), label_of(m[2], "--relabel"));
  }
  for (const auto& spec : o.names) {
    static const std::regex pattern(R"(^(\d+)=(.+)$)");
    std::smatch m;
    if (!std::regex_match(spec, m, pattern))
      throw core::UsageError("--name " + spec + ": expected LABEL=NAME");
    labels.names[label_of(m[1], "--name")] = m[2];
  }

  const auto counts = core::label_counts(labels);
  if (counts.empty()) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t v = 0; v < volume.voxel_count(); ++v) {
      lo = std::min(lo, volume.value(v));
      hi = std::max(hi, volume.value(v));
    }
    throw core::InputError("the segmentation labels no voxel (values range from " +
                               std::to_string(lo) + " to " + std::to_string(hi) + ")",
                           {o.input, "", ""});
  }
  {
    exporters::StagedOutput staged(o.output);
    core::write_label_map_vti(labels, staged.main_file());
    staged.commit();
  }
  const std::string output = std::filesystem::absolute(o.output).lexically_normal().string();
  if (o.json) {
    nlohmann::json json = {{"output", output},
                           {"dims", {volume.dims[0], volume.dims[1], volume.dims[2]}}};
    const double voxel_ml = volume.spacing.prod() * 1e6;
    for (const auto& [label, count] : counts) {
      const auto name = labels.names.find(label);
      json["labels"].push_back({{"label", label},
                                {"name", name == labels.names.end() ? "" : name->second},
                                {"voxels", count},
                                {"volume_ml", static_cast<double>(count) * voxel_ml}});
    }
    print_json(json);
  } else {
    std::string text = "wrote " + output + "\n";
    for (const auto& [label, count] : counts) {
      text += "  label " + std::to_string(label) + ": " + std::to_string(count) + " voxels\n";
    }
    print_text(text);
  }
}

}  // namespace

void add_segment_commands(CLI::App& app) {
  auto o = std::make_shared<SegmentOptions>();
  auto* command = app.add_subcommand(
      "segment",
      "Segment an image volume into a label map (.vti): thresholds, region growing, "
      "opening/closing, largest component, label arithmetic — in that order");
  command->add_option("input", o->input, "Volume file or DICOM folder")->required();
  command->add_option("-o,--output", o->output, "Label map to write (.vti)")->required();
  command->add_option("--threshold", o->thresholds,
                      "LO:HI[=LABEL]: values in [LO, HI] get LABEL (default 1)");
  command->add_option(
      "--grow", o->grows,
      "X,Y,Z[:TOL][=LABEL]: grow from the point (mm, patient LPS) through 6-connected "
      "voxels within TOL of the seed value");
  command->add_option("--open", o->open, "Opening with a ball of R voxels")
      ->check(CLI::PositiveNumber);
  command->add_option("--close", o->close, "Closing with a ball of R voxels")
      ->check(CLI::PositiveNumber);
  command->add_flag("--largest", o->largest, "Keep each label's largest 6-connected component");
  command->add_option("--merge", o->merges, "A,B,…=C: labels A, B, … become C");
  command->add_option("--remove", o->removes, "Label L becomes background");
  command->add_option("--relabel", o->relabels, "A=B: label A becomes B");
  command->add_option("--name", o->names, "LABEL=NAME: tissue name stored with the label");
  command->add_flag("--json", o->json, "Print JSON");
  command->add_option("--max-memory", o->max_memory_mib, "Largest voxel buffer to allocate, MiB")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->callback([o] { segment(*o); });
}

}  // namespace viscera::cli
