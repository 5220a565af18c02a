#include "importers/volume/dicom_series.h"

#include <gdcmAttribute.h>
#include <gdcmDirectory.h>
#include <gdcmReader.h>
#include <gdcmTrace.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "importers/volume/dicom_element_lengths.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/gdcm_parse_guard.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

std::string text_of(const gdcm::DataSet& data, const gdcm::Tag& tag) {
  if (!data.FindDataElement(tag)) return {};
  const gdcm::ByteValue* bytes = data.GetDataElement(tag).GetByteValue();
  if (bytes == nullptr) return {};
  std::string text(bytes->GetPointer(), bytes->GetLength());
  while (!text.empty() && (text.back() == ' ' || text.back() == '\0'))
    text.pop_back();
  while (!text.empty() && text.front() == ' ')
    text.erase(text.begin());
  return text;
}

/// The backslash-separated decimal numbers of a DS or IS value.
std::vector<double> numbers_of(const std::string& text) {
  std::vector<double> values;
  std::istringstream parts(text);
  for (std::string part; std::getline(parts, part, '\\');) {
    try {
      values.push_back(std::stod(part));
    } catch (const std::exception&) {
      return {};
    }
  }
  return values;
}

template <std::uint16_t Group, std::uint16_t Element>
int unsigned_short_of(const gdcm::DataSet& data) {
  if (!data.FindDataElement(gdcm::Tag(Group, Element))) return 0;
  gdcm::Attribute<Group, Element> attribute;
  attribute.SetFromDataSet(data);
  return static_cast<int>(attribute.GetValue());
}

}  // namespace

bool has_dicom_magic(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[132] = {};
  in.read(magic, sizeof magic);
  return in.gcount() == sizeof magic && std::string(magic + 128, 4) == "DICM";
}

bool read_dicom_header(const fs::path& file, DicomHeader& header) {
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetDebug(false);
  gdcm::Trace::SetError(false);
  gdcm::Reader reader;
  reader.SetFileName(file.string().c_str());
  if (!reader.ReadUpToTag(gdcm::Tag(0x7fe0, 0x0010))) return false;
  const gdcm::DataSet& data = reader.GetFile().GetDataSet();
  header = DicomHeader{};
  header.file = file;
  const gdcm::TransferSyntax syntax = reader.GetFile().GetHeader().GetDataSetTransferSyntax();
  header.deflated = syntax == gdcm::TransferSyntax::DeflatedExplicitVRLittleEndian;
  header.native = syntax == gdcm::TransferSyntax::ImplicitVRLittleEndian ||
                  syntax == gdcm::TransferSyntax::ExplicitVRLittleEndian ||
                  syntax == gdcm::TransferSyntax::ExplicitVRBigEndian;
  header.has_number_of_frames = data.FindDataElement(gdcm::Tag(0x0028, 0x0008));
  header.rows = unsigned_short_of<0x0028, 0x0010>(data);
  header.columns = unsigned_short_of<0x0028, 0x0011>(data);
  if (header.rows <= 0 || header.columns <= 0) return false;  // not an image (report, plan, …)
  header.samples = std::max(1, unsigned_short_of<0x0028, 0x0002>(data));
  header.bits_allocated = unsigned_short_of<0x0028, 0x0100>(data);
  header.series_uid = text_of(data, gdcm::Tag(0x0020, 0x000e));
  header.description = text_of(data, gdcm::Tag(0x0008, 0x103e));
  header.modality = text_of(data, gdcm::Tag(0x0008, 0x0060));
  header.photometric = text_of(data, gdcm::Tag(0x0028, 0x0004));
  auto spacing = numbers_of(text_of(data, gdcm::Tag(0x0028, 0x0030)));
  if (spacing.size() != 2) spacing = numbers_of(text_of(data, gdcm::Tag(0x0018, 0x1164)));
  if (spacing.size() == 2 && spacing[0] > 0 && spacing[1] > 0) {
    header.pixel_spacing = core::Vec2(spacing[1], spacing[0]);  // (between columns, between rows)
  }
  header.has_pixel_spacing = header.pixel_spacing.x() > 0;
  if (const auto slope = numbers_of(text_of(data, gdcm::Tag(0x0028, 0x1053))); slope.size() == 1) {
    header.slope = slope[0];
  }
  if (const auto intercept = numbers_of(text_of(data, gdcm::Tag(0x0028, 0x1052)));
      intercept.size() == 1) {
    header.intercept = intercept[0];
  }
  if (const auto frames = numbers_of(text_of(data, gdcm::Tag(0x0028, 0x0008)));
      frames.size() == 1) {
    header.frames = std::max(1, static_cast<int>(frames[0]));
  }
  if (const auto instance = numbers_of(text_of(data, gdcm::Tag(0x0020, 0x0013)));
      instance.size() == 1) {
    header.instance = static_cast<int>(instance[0]);
  }
  if (const auto position = numbers_of(text_of(data, gdcm::Tag(0x0020, 0x0032)));
      position.size() == 3) {
    header.position = core::Vec3(position[0], position[1], position[2]);
    header.has_position = header.position.allFinite();
  }
  if (const auto cosines = numbers_of(text_of(data, gdcm::Tag(0x0020, 0x0037)));
      cosines.size() == 6) {
    const core::Vec3 row(cosines[0], cosines[1], cosines[2]),
        column(cosines[3], cosines[4], cosines[5]);
    if (row.allFinite() && column.allFinite() && row.norm() > 0.5 && column.norm() > 0.5) {
      header.row_direction = row.normalized();
      header.column_direction = column.normalized();
      header.has_orientation = true;
    }
  }
  return true;
}

std::optional<std::string> gdcm_cannot_read(const DicomHeader& header) {
  if (header.modality == "RTDOSE" && !header.has_number_of_frames)
    return "RT Dose file without Number of Frames (0028,0008), which GDCM 3.0 needs to read it";
  if (header.image_reader_aborts) return kGdcmAbortReason;
  return std::nullopt;
}

std::vector<std::vector<DicomHeader>> dicom_series_in(const fs::path& folder,
                                                      std::vector<SkippedFile>& skipped) {
  gdcm::Directory directory;
  directory.Load(folder.string(), true);
  std::vector<std::string> names = directory.GetFilenames();
  std::sort(names.begin(), names.end());
  // A file whose element lengths run past its end is skipped before GDCM allocates them.
  std::vector<fs::path> files;
  for (const auto& name : names) {
    if (auto problem = dicom_length_problem(name))
      skipped.push_back({name, std::move(*problem)});
    else
      files.emplace_back(name);
  }
  const std::vector<GdcmGuardResult> guard = gdcm_reads_without_abort(files);
  std::map<std::string, std::vector<DicomHeader>> by_uid;
  for (std::size_t f = 0; f < files.size(); ++f) {
    if (!guard[f].parses) {
      skipped.push_back({files[f], kGdcmAbortReason});
      continue;
    }
    DicomHeader header;
    if (!read_dicom_header(files[f], header)) continue;  // not an image: not part of a series
    header.image_reader_aborts = !guard[f].image_reads;
    if (auto reason = gdcm_cannot_read(header)) {
      skipped.push_back({files[f], std::move(*reason)});
      continue;
    }
    by_uid[header.series_uid].push_back(std::move(header));
  }
  if (by_uid.empty()) {
    const std::string damaged =
        skipped.empty() ? "" : ", " + std::to_string(skipped.size()) + " of them damaged";
    throw core::InputError("folder holds no DICOM image (" + std::to_string(names.size()) +
                               " files looked at" + damaged + ")",
                           {folder.string(), "", ""});
  }
  std::vector<std::vector<DicomHeader>> series;
  for (auto& [uid, headers] : by_uid)
    series.push_back(std::move(headers));
  std::stable_sort(series.begin(), series.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return series;
}

DicomSeriesSummary summarize(const std::vector<DicomHeader>& series) {
  DicomSeriesSummary summary;
  summary.uid = series.front().series_uid;
  summary.description = series.front().description;
  summary.modality = series.front().modality;
  summary.files = static_cast<int>(series.size());
  return summary;
}

StackedSlices stack_slices(std::vector<DicomHeader> series, const std::string& folder) {
  const std::string uid = "series " + series.front().series_uid + ": ";
  const DicomHeader& first = series.front();
  for (const auto& slice : series) {
    if (!slice.has_position || !slice.has_orientation) {
      throw core::InputError(uid + slice.file.filename().string() +
                                 " has no Image Position/Orientation (Patient), so the slices "
                                 "cannot be ordered",
                             {folder, "", ""});
    }
    if ((slice.row_direction - first.row_direction).norm() > 1e-4 ||
        (slice.column_direction - first.column_direction).norm() > 1e-4) {
      throw core::InputError(uid + "slices are not parallel (" + slice.file.filename().string() +
                                 " is oriented differently from " + first.file.filename().string() +
                                 ")",
                             {folder, "", ""});
    }
    if (slice.rows != first.rows || slice.columns != first.columns) {
      throw core::InputError(uid + "slices differ in size (" + slice.file.filename().string() + ")",
                             {folder, "", ""});
    }
    if (slice.frames != 1) {
      throw core::InputError(uid + "several files of which " + slice.file.filename().string() +
                                 " holds several frames; read that file on its own",
                             {folder, "", ""});
    }
  }
  const core::Vec3 normal = first.row_direction.cross(first.column_direction).normalized();
  std::stable_sort(series.begin(), series.end(), [&](const DicomHeader& a, const DicomHeader& b) {
    return a.position.dot(normal) < b.position.dot(normal);
  });
  StackedSlices stacked;
  if (series.size() > 1) {
    std::vector<double> gaps;
    for (std::size_t s = 1; s < series.size(); ++s) {
      gaps.push_back((series[s].position - series[s - 1].position).dot(normal));
    }
    double mean = 0;
    for (const double gap : gaps)
      mean += gap;
    mean /= static_cast<double>(gaps.size());
    for (std::size_t s = 0; s < gaps.size(); ++s) {
      if (gaps[s] < 1e-6) {
        throw core::InputError(uid + series[s].file.filename().string() + " and " +
                                   series[s + 1].file.filename().string() +
                                   " lie in the same plane",
                               {folder, "", ""});
      }
      if (std::abs(gaps[s] - mean) > 0.01 * mean) {
        std::ostringstream message;
        message << uid << "slices are not evenly spaced: " << gaps[s] << " mm between "
                << series[s].file.filename().string() << " and "
                << series[s + 1].file.filename().string() << ", " << mean << " mm on average";
        throw core::InputError(message.str(), {folder, "", ""});
      }
    }
    stacked.spacing_mm = mean;
  }
  stacked.slices = std::move(series);
  return stacked;
}

}  // namespace viscera::importers::detail
