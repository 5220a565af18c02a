// DICOM through GDCM (libgdcm, the library under vtkgdcm). A folder is searched with its
// sub-folders; its images are grouped by Series Instance UID and the series with the most files
// is read, the others listed. Slices are ordered by Image Position (Patient) along the normal of
// Image Orientation (Patient) (dicom_series.cpp). A single file may hold several frames.
// GDCM's own ImageReader decodes each file rather than vtkGDCMImageReader, whose Shift/Scale
// are documented as inaccurate when Rescale Slope/Intercept vary along a series: here they are
// applied per slice. DICOM's patient frame is LPS in mm, the frame of ImageVolume.
#include <fcntl.h>
#include <gdcmImage.h>
#include <gdcmImageReader.h>
#include <gdcmTrace.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

#include "core/error.h"
#include "importers/volume/dicom_element_lengths.h"
#include "importers/volume/dicom_series.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/gdcm_parse_guard.h"
#include "importers/volume/volume_geometry.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

/// Sends file descriptor 2 to /dev/null while it lives: the JPEG and JPEG 2000 codecs under
/// GDCM print their complaints straight to stderr, and a failure is reported once, as a typed
/// error naming the file. Process-wide; not for concurrent use.
class ScopedStderrSilence {
 public:
  ScopedStderrSilence() : saved_(::dup(2)) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) ::dup2(null, 2);
    if (null >= 0) ::close(null);
  }
  ~ScopedStderrSilence() {
    if (saved_ >= 0) {
      ::dup2(saved_, 2);
      ::close(saved_);
    }
  }
  ScopedStderrSilence(const ScopedStderrSilence&) = delete;
  ScopedStderrSilence& operator=(const ScopedStderrSilence&) = delete;

 private:
  int saved_;
};

/// gdcm::ImageReader::Read() with the codecs' stderr chatter silenced (JPEG 2000 headers are
/// parsed while reading).
bool silently_read(gdcm::ImageReader& reader) {
  const ScopedStderrSilence silence;
  return reader.Read();
}

/// The ImageVolume type that holds a file's samples without loss.
core::ScalarType output_type(const gdcm::PixelFormat& format, const std::string& file) {
  if (format.GetSamplesPerPixel() == 3) return core::ScalarType::Float32;  // luminance
  switch (format.GetScalarType()) {
    case gdcm::PixelFormat::SINGLEBIT:
    case gdcm::PixelFormat::UINT8:
      return core::ScalarType::UInt8;
    case gdcm::PixelFormat::INT8:
    case gdcm::PixelFormat::INT12:
    case gdcm::PixelFormat::INT16:
      return core::ScalarType::Int16;
    case gdcm::PixelFormat::UINT12:
    case gdcm::PixelFormat::UINT16:
      return core::ScalarType::UInt16;
    case gdcm::PixelFormat::INT32:
      return core::ScalarType::Int32;
    case gdcm::PixelFormat::FLOAT32:
      return core::ScalarType::Float32;
    case gdcm::PixelFormat::UINT32:
    case gdcm::PixelFormat::FLOAT64:
      return core::ScalarType::Float64;
    default:
      throw core::InputError(
          std::string("unsupported pixel type ") + format.GetScalarTypeAsString(), {file, "", ""});
  }
}

/// Sample `index` of a decoded buffer as double.
double sample(const char* buffer, gdcm::PixelFormat::ScalarType type, std::size_t index) {
  const auto read = [&](auto zero) {
    decltype(zero) value;
    std::memcpy(&value, buffer + index * sizeof value, sizeof value);
    return static_cast<double>(value);
  };
  switch (type) {
    case gdcm::PixelFormat::SINGLEBIT:  // packed, first pixel in the lowest bit
      return (static_cast<unsigned char>(buffer[index / 8]) >> (index % 8)) & 1u;
    case gdcm::PixelFormat::UINT8:
      return read(std::uint8_t{});
    case gdcm::PixelFormat::INT8:
      return read(std::int8_t{});
    case gdcm::PixelFormat::UINT12:
    case gdcm::PixelFormat::UINT16:
      return read(std::uint16_t{});
    case gdcm::PixelFormat::INT12:
    case gdcm::PixelFormat::INT16:
      return read(std::int16_t{});
    case gdcm::PixelFormat::UINT32:
      return read(std::uint32_t{});
    case gdcm::PixelFormat::INT32:
      return read(std::int32_t{});
    case gdcm::PixelFormat::FLOAT32:
      return read(float{});
    case gdcm::PixelFormat::FLOAT64:
      return read(double{});
    default:
      return 0.0;
  }
}

template <typename T>
void store(core::ImageVolume& volume, std::size_t index, double value) {
  reinterpret_cast<T*>(volume.voxels.data())[index] =
      static_cast<T>(std::is_integral_v<T> ? std::round(value) : value);
}

void store_value(core::ImageVolume& volume, std::size_t index, double value) {
  switch (volume.scalar_type) {
    case core::ScalarType::UInt8:
      store<std::uint8_t>(volume, index, value);
      break;
    case core::ScalarType::Int16:
      store<std::int16_t>(volume, index, value);
      break;
    case core::ScalarType::UInt16:
      store<std::uint16_t>(volume, index, value);
      break;
    case core::ScalarType::Int32:
      store<std::int32_t>(volume, index, value);
      break;
    case core::ScalarType::Float32:
      store<float>(volume, index, value);
      break;
    case core::ScalarType::Float64:
      store<double>(volume, index, value);
      break;
  }
}

/// The bytes a file holds after the start of its (native) Pixel Data value: the first element
/// tagged (7FE0,0010) whose declared length is at least `expected` (an icon's pixel data comes
/// earlier and is smaller). Little- and big-endian, explicit and implicit VR. The file size
/// when no such element is found (GDCM then decides).
std::uint64_t native_pixel_bytes(const fs::path& path, std::uint64_t expected) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto u32 = [&](std::size_t at, bool big) {
    std::uint32_t value = 0;
    for (int b = 0; b < 4; ++b) {
      const auto byte = static_cast<unsigned char>(bytes[at + (big ? b : 3 - b)]);
      value = (value << 8) | byte;
    }
    return value;
  };
  for (const bool big : {false, true}) {
    const std::string tag =
        big ? std::string("\x7f\xe0\x00\x10", 4) : std::string("\xe0\x7f\x10\x00", 4);
    for (auto at = bytes.find(tag); at != std::string::npos; at = bytes.find(tag, at + 1)) {
      if (at + 12 > bytes.size()) break;
      const std::string vr = bytes.substr(at + 4, 2);
      const bool explicit_vr = vr == "OB" || vr == "OW";
      const std::size_t value = at + (explicit_vr ? 12 : 8);
      const std::uint32_t length = u32(explicit_vr ? at + 8 : at + 4, big);
      if (length != 0xffffffffu && length >= expected) return bytes.size() - value;
    }
  }
  return bytes.size();
}

/// Refuses, naming the file, what GDCM 3.0 cannot read without failing an assertion.
void check_readable(const DicomHeader& header) {
  if (auto reason = gdcm_cannot_read(header))
    throw core::InputError(*reason, {header.file.string(), "", ""});
}

/// Refuses, before any voxel is allocated, a file of uncompressed pixel data smaller than the
/// image its header declares: rows × columns × frames × samples × Bits Allocated / 8 bytes, with
/// 2 samples a pixel for chroma-subsampled YBR 4:2:2 and 1.5 for 4:2:0. Compressed and deflated
/// files may hold fewer bytes than their image and are left to the decoder.
void check_declared_pixels_fit(const DicomHeader& header) {
  if (!header.native || header.deflated || header.bits_allocated <= 0) return;
  const auto ends_with = [&](const char* suffix) {
    const std::string text = suffix;
    return header.photometric.size() >= text.size() &&
           header.photometric.compare(header.photometric.size() - text.size(), text.size(), text) ==
               0;
  };
  const double samples = ends_with("_422") ? 2.0 : ends_with("_420") ? 1.5 : header.samples;
  const double needed = static_cast<double>(header.rows) * header.columns * header.frames *
                        samples * header.bits_allocated / 8.0;
  std::error_code error;
  const auto size = fs::file_size(header.file, error);
  if (error || needed <= static_cast<double>(size)) return;
  std::ostringstream reason;
  reason << "pixel data is truncated: the header declares " << header.columns << "×" << header.rows
         << " pixels × " << header.frames << " frames × " << samples << " samples of "
         << header.bits_allocated << " bits (" << std::fixed << std::setprecision(0) << needed
         << " bytes), the file has " << size << " bytes";
  throw core::InputError(reason.str(), {header.file.string(), "", ""});
}

/// Decodes one file and writes its frames into `volume` from voxel `first` on, each value as
/// slope·value + intercept. Throws naming the file when GDCM cannot read or decode it.
void decode_into(const fs::path& path, const DicomHeader& header, double slope, double intercept,
                 core::ImageVolume& volume, std::size_t first) {
  const std::string file = path.string();
  check_readable(header);
  gdcm::ImageReader reader;
  reader.SetFileName(file.c_str());
  if (!silently_read(reader)) {
    throw core::InputError("GDCM cannot read the image: the file is truncated or corrupt",
                           {file, "", ""});
  }
  const gdcm::Image& image = reader.GetImage();
  const gdcm::PixelFormat& format = image.GetPixelFormat();
  const std::size_t columns = image.GetDimension(0), rows = image.GetDimension(1);
  const std::size_t frames = image.GetNumberOfDimensions() > 2 ? image.GetDimension(2) : 1;
  if (static_cast<int>(columns) != header.columns || static_cast<int>(rows) != header.rows ||
      static_cast<int>(frames) != header.frames) {
    throw core::InputError("image size differs from the header", {file, "", ""});
  }
  const std::size_t pixels = columns * rows * frames;
  const std::size_t samples = format.GetSamplesPerPixel();
  const bool single_bit = format.GetScalarType() == gdcm::PixelFormat::SINGLEBIT;
  const std::size_t expected =
      single_bit ? (pixels * samples + 7) / 8 : pixels * format.GetPixelSize();
  const auto photometric = image.GetPhotometricInterpretation();
  if (photometric == gdcm::PhotometricInterpretation::YBR_FULL_422 ||
      photometric == gdcm::PhotometricInterpretation::YBR_PARTIAL_422 ||
      photometric == gdcm::PhotometricInterpretation::YBR_PARTIAL_420) {
    if (!image.GetTransferSyntax().IsEncapsulated()) {
      throw core::InputError(std::string("uncompressed chroma-subsampled colour (") +
                                 photometric.GetString() + ") is not supported",
                             {file, "", ""});
    }
  }
  // Native pixel data that ends before the image does: GDCM would pad it silently.
  if (!image.GetTransferSyntax().IsEncapsulated() && !header.deflated && !single_bit) {
    const std::uint64_t present = native_pixel_bytes(path, expected);
    if (present < expected) {
      throw core::InputError("pixel data is truncated: the image needs " +
                                 std::to_string(expected) + " bytes, the file holds " +
                                 std::to_string(present),
                             {file, "", ""});
    }
  }
  std::vector<char> buffer(image.GetBufferLength());
  bool decoded = false;
  {
    const ScopedStderrSilence silence;
    decoded = buffer.size() >= expected && image.GetBuffer(buffer.data());
  }
  if (!decoded) {
    throw core::InputError(std::string("GDCM cannot decode the pixel data (transfer syntax ") +
                               image.GetTransferSyntax().GetString() +
                               "): it is truncated or its compression is not supported",
                           {file, "", ""});
  }
  if (samples != 1 && samples != 3) {
    throw core::InputError(
        "images with " + std::to_string(samples) + " samples per pixel are not supported",
        {file, "", ""});
  }
  const auto type = format.GetScalarType();
  if (samples == 1) {
    if (slope == 1.0 && intercept == 0.0 && !single_bit &&
        core::scalar_size(volume.scalar_type) == format.GetPixelSize() &&
        output_type(format, file) == volume.scalar_type) {
      std::memcpy(volume.voxels.data() + first * format.GetPixelSize(), buffer.data(),
                  pixels * format.GetPixelSize());
      return;
    }
    for (std::size_t p = 0; p < pixels; ++p) {
      store_value(volume, first + p, slope * sample(buffer.data(), type, p) + intercept);
    }
    return;
  }
  // Colour: Rec. 601 luminance of RGB; the Y of YBR is that luminance already.
  const bool ybr = photometric != gdcm::PhotometricInterpretation::RGB;
  const bool planar = image.GetPlanarConfiguration() == 1;
  const std::size_t frame_pixels = columns * rows;
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::size_t frame = p / frame_pixels, in_frame = p % frame_pixels;
    const auto at = [&](std::size_t s) {
      return planar ? (frame * 3 + s) * frame_pixels + in_frame : p * 3 + s;
    };
    const double y = ybr ? sample(buffer.data(), type, at(0))
                         : 0.299 * sample(buffer.data(), type, at(0)) +
                               0.587 * sample(buffer.data(), type, at(1)) +
                               0.114 * sample(buffer.data(), type, at(2));
    store_value(volume, first + p, slope * y + intercept);
  }
}

/// Bytes per voxel the output may need, from the header alone (for the memory check).
std::int64_t output_bytes(const DicomHeader& header) {
  if (header.samples == 3) return 4;
  if (header.bits_allocated <= 8) return 2;
  return header.bits_allocated <= 16 ? 2 : 8;
}

/// The decoded pixel format of `file` without its pixel data: GDCM reads the header only.
gdcm::PixelFormat pixel_format_of(const DicomHeader& header) {
  check_readable(header);
  const fs::path& path = header.file;
  gdcm::ImageReader reader;
  reader.SetFileName(path.string().c_str());
  if (!silently_read(reader)) {
    throw core::InputError("GDCM cannot read the image: the file is truncated or corrupt",
                           {path.string(), "", ""});
  }
  return reader.GetImage().GetPixelFormat();
}

/// Voxels and geometry of slices (one file with one or more frames, or several one-frame
/// files in order) into `loaded`.
void assemble(const std::vector<DicomHeader>& slices, double slice_spacing_mm,
              const VolumeReadOptions& options, const std::string& where, LoadedVolume& loaded) {
  const DicomHeader& first = slices.front();
  const std::int64_t depth = first.frames * static_cast<std::int64_t>(slices.size());
  check_voxel_budget({first.columns, first.rows, depth}, 1, output_bytes(first), options, where);

  bool uniform_rescale = true;
  for (const auto& slice : slices) {
    uniform_rescale =
        uniform_rescale && slice.slope == first.slope && slice.intercept == first.intercept;
  }
  core::ImageVolume& volume = loaded.volume;
  volume.dims = {first.columns, first.rows, static_cast<int>(depth)};
  volume.scalar_type = uniform_rescale ? output_type(pixel_format_of(first), first.file.string())
                                       : core::ScalarType::Float32;
  for (const auto& slice : slices)
    check_declared_pixels_fit(slice);
  volume.allocate();
  const std::size_t per_file = static_cast<std::size_t>(first.columns) * first.rows * first.frames;
  for (std::size_t s = 0; s < slices.size(); ++s) {
    const double slope = uniform_rescale || slices[s].slope == 0.0 ? 1.0 : slices[s].slope;
    const double intercept = uniform_rescale ? 0.0 : slices[s].intercept;
    decode_into(slices[s].file, slices[s], slope, intercept, volume, s * per_file);
    loaded.files.push_back(slices[s].file);
  }
  if (uniform_rescale) apply_rescale(volume, first.slope, first.intercept);

  // Geometry: GDCM's spacing is (column step, row step, frame step) in mm.
  gdcm::ImageReader reader;
  reader.SetFileName(first.file.string().c_str());
  silently_read(reader);
  const gdcm::Image& image = reader.GetImage();
  double frame_step = slice_spacing_mm;
  if (first.frames > 1) {
    frame_step = std::abs(image.GetSpacing(2));
    if (!(frame_step > 0.0)) {
      frame_step = 1.0;
      loaded.notes.push_back("frames carry no spacing; 1 mm assumed between them");
    }
  }
  if (!first.has_pixel_spacing && image.GetSpacing(0) == 1.0 && image.GetSpacing(1) == 1.0)
    loaded.notes.push_back("file gives no Pixel Spacing; 1 mm assumed");
  if (!first.has_orientation || !first.has_position) {
    loaded.notes.push_back(
        "file gives no Image Position/Orientation (Patient); axes taken as "
        "aligned with the patient");
  }
  const core::Vec3 normal = first.row_direction.cross(first.column_direction).normalized();
  core::Mat3 axes;
  // Pixel Spacing as the file states it; GDCM ignores it for some storage classes (NM, SC)
  // but finds it in functional groups of enhanced objects.
  const core::Vec2 pixel = first.has_pixel_spacing
                               ? first.pixel_spacing
                               : core::Vec2(image.GetSpacing(0), image.GetSpacing(1));
  axes.col(0) = first.row_direction * pixel.x();
  axes.col(1) = first.column_direction * pixel.y();
  axes.col(2) = normal * frame_step;
  set_geometry_mm(volume, axes, first.position, false, where);
}

}  // namespace

LoadedVolume read_dicom(const fs::path& path, const VolumeReadOptions& options) {
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetError(false);
  LoadedVolume loaded;
  loaded.format = "DICOM";
  if (fs::is_directory(path)) {
    auto series = dicom_series_in(path, loaded.skipped_files);
    for (std::size_t s = 1; s < series.size(); ++s)
      loaded.other_series.push_back(summarize(series[s]));
    if (series.front().size() == 1) {
      assemble(series.front(), 1.0, options, series.front().front().file.string(), loaded);
    } else {
      const StackedSlices stacked = stack_slices(std::move(series.front()), path.string());
      assemble(stacked.slices, stacked.spacing_mm, options, path.string(), loaded);
    }
    return loaded;
  }
  // GDCM allocates each value at its declared length before reading it: lengths first.
  if (const auto problem = dicom_length_problem(path))
    throw core::InputError(*problem, {path.string(), "", ""});
  const GdcmGuardResult guard = gdcm_reads_without_abort({path}).front();
  if (!guard.parses) throw core::InputError(kGdcmAbortReason, {path.string(), "", ""});
  DicomHeader header;
  if (!read_dicom_header(path, header)) {
    throw core::InputError(
        "not a DICOM image (GDCM finds no readable header with rows and columns)",
        {path.string(), "", ""});
  }
  header.image_reader_aborts = !guard.image_reads;
  assemble({header}, 1.0, options, path.string(), loaded);
  return loaded;
}

}  // namespace viscera::importers::detail
