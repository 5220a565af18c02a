// NRRD (.nrrd with its data attached, or .nhdr naming a data file) read here, header and
// voxels. VTK 9.1's vtkNrrdReader misreads plain 3D files (a "sizes: 4 3 2" short volume comes
// out as 3 × 2 × 1 with 3 components, see tests/importers/volume_formats_test.cpp) and keeps
// only the lengths of "space directions". Supported: 3D scalar volumes of the integer and
// floating types, raw or gzip encoding, either endianness, "byte skip" ≥ 0. Geometry: space
// directions (the world step of each axis, mm), space origin, and the space they are in (RAS
// and LPS spellings); without them, "spacings".
#include <zlib.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/volume_geometry.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

struct NrrdHeader {
  std::map<std::string, std::string> fields;
  std::vector<core::Vec3> directions;  ///< one per spatial axis, in the file's space units
  core::Vec3 origin = core::Vec3::Zero();
  std::uint64_t data_offset = 0;  ///< where attached data starts
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
  bool ended = false;
  for (int lines = 0; lines < 1000 && std::getline(in, line); ++lines) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) {
      ended = true;
      break;
    }
    if (line[0] == '#') continue;
    const auto colon = line.find(": ");
    if (colon == std::string::npos) continue;  // key:=value pairs carry no geometry
    header.fields[line.substr(0, colon)] = line.substr(colon + 2);
  }
  header.data_offset = ended && in ? static_cast<std::uint64_t>(in.tellg()) : 0;
  try {
    if (const auto it = header.fields.find("space directions"); it != header.fields.end()) {
      header.directions = vectors_of(it->second);
    }
    if (const auto it = header.fields.find("space origin"); it != header.fields.end()) {
      const auto origin = vectors_of(it->second);
      if (origin.size() == 1) header.origin = origin[0];
    }
  } catch (const std::exception&) {
    throw core::InputError("space directions or origin hold a number that cannot be read",
                           {file, "", ""});
  }
  if (!ended && header.fields.count("data file") == 0) {
    throw core::InputError("header ends without the blank line before the data", {file, "", ""});
  }
  return header;
}

/// (ImageVolume type, bytes per sample, is integer and signed, is float) of a NRRD type name.
struct SampleType {
  core::ScalarType type;
  int bytes;
  bool is_signed, is_float;
};

SampleType sample_type_of(const std::string& name, const std::string& file) {
  static const std::map<std::string, SampleType> types = {
      {"uchar", {core::ScalarType::UInt8, 1, false, false}},
      {"unsigned char", {core::ScalarType::UInt8, 1, false, false}},
      {"uint8", {core::ScalarType::UInt8, 1, false, false}},
      {"uint8_t", {core::ScalarType::UInt8, 1, false, false}},
      {"signed char", {core::ScalarType::Int16, 1, true, false}},
      {"int8", {core::ScalarType::Int16, 1, true, false}},
      {"int8_t", {core::ScalarType::Int16, 1, true, false}},
      {"short", {core::ScalarType::Int16, 2, true, false}},
      {"int16", {core::ScalarType::Int16, 2, true, false}},
      {"int16_t", {core::ScalarType::Int16, 2, true, false}},
      {"ushort", {core::ScalarType::UInt16, 2, false, false}},
      {"unsigned short", {core::ScalarType::UInt16, 2, false, false}},
      {"uint16", {core::ScalarType::UInt16, 2, false, false}},
      {"uint16_t", {core::ScalarType::UInt16, 2, false, false}},
      {"int", {core::ScalarType::Int32, 4, true, false}},
      {"int32", {core::ScalarType::Int32, 4, true, false}},
      {"int32_t", {core::ScalarType::Int32, 4, true, false}},
      {"uint", {core::ScalarType::Float64, 4, false, false}},
      {"unsigned int", {core::ScalarType::Float64, 4, false, false}},
      {"uint32", {core::ScalarType::Float64, 4, false, false}},
      {"uint32_t", {core::ScalarType::Float64, 4, false, false}},
      {"float", {core::ScalarType::Float32, 4, true, true}},
      {"double", {core::ScalarType::Float64, 8, true, true}},
  };
  const auto it = types.find(name);
  if (it == types.end())
    throw core::InputError("unsupported NRRD type \"" + name + "\"", {file, "", ""});
  return it->second;
}

/// `count` bytes from `path` after `offset`, inflating gzip data; throws naming `shown` when
/// fewer are there.
std::string read_data(const fs::path& path, std::uint64_t offset, std::uint64_t count, bool gzip,
                      const std::string& shown) {
  // What the file can hold is known before the voxels are allocated: raw data is at most the
  // bytes after the header, gzip data at most deflate's 1032:1 of them (the volume_nrrd fuzz
  // target's slow unit: a 139-byte header asking for 1.96 GB took 2 GB and 3.4 s to refuse).
  std::error_code error;
  const std::uint64_t size = fs::file_size(path, error);
  const std::uint64_t after = !error && size > offset ? size - offset : 0;
  const std::uint64_t most = gzip ? 1032 * after + 64 : after;
  if (count > most) {
    throw core::InputError("file is truncated: the header asks for " + std::to_string(count) +
                               " bytes of voxels, the file holds " + std::to_string(after) +
                               (gzip ? " bytes of gzip data, which cannot inflate to that" : ""),
                           {shown, "", ""});
  }
  std::string bytes(count, '\0');
  std::uint64_t got = 0;
  if (gzip) {
    std::ifstream in(path, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(offset));
    const std::string packed((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
    z_stream stream{};
    if (inflateInit2(&stream, 15 + 32) != Z_OK)
      throw core::InputError("zlib cannot start", {shown, "", ""});
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
    stream.avail_in = static_cast<uInt>(packed.size());
    stream.next_out = reinterpret_cast<Bytef*>(bytes.data());
    stream.avail_out = static_cast<uInt>(count);
    const int status = inflate(&stream, Z_FINISH);
    got = stream.total_out;
    inflateEnd(&stream);
    if (status != Z_STREAM_END && status != Z_OK && status != Z_BUF_ERROR) {
      throw core::InputError("gzip data is corrupt", {shown, "", ""});
    }
  } else {
    std::ifstream in(path, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(offset));
    in.read(bytes.data(), static_cast<std::streamsize>(count));
    got = static_cast<std::uint64_t>(std::max<std::streamsize>(in.gcount(), 0));
  }
  if (got < count) {
    throw core::InputError("file is truncated: the header asks for " + std::to_string(count) +
                               " bytes of voxels, the file holds " + std::to_string(got),
                           {shown, "", ""});
  }
  return bytes;
}

bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace

LoadedVolume read_nrrd(const fs::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  const NrrdHeader header = read_header(path, file);
  const auto field = [&](const std::string& key) {
    const auto it = header.fields.find(key);
    if (it == header.fields.end())
      throw core::InputError("header has no \"" + key + "\" field", {file, "", ""});
    return it->second;
  };
  if (field("dimension") != "3") {
    throw core::InputError("only 3D NRRD volumes are read (dimension: " + field("dimension") + ")",
                           {file, "", ""});
  }
  std::array<std::int64_t, 3> dims{};
  {
    std::istringstream sizes(field("sizes"));
    for (auto& d : dims) {
      if (!(sizes >> d))
        throw core::InputError("sizes does not give three numbers", {file, "", ""});
    }
  }
  const SampleType sample = sample_type_of(field("type"), file);
  check_voxel_budget(dims, 1, std::max<std::int64_t>(sample.bytes, core::scalar_size(sample.type)),
                     options, file);
  const std::string encoding = field("encoding");
  const bool gzip = encoding == "gzip" || encoding == "gz";
  if (!gzip && encoding != "raw") {
    throw core::InputError("NRRD encoding \"" + encoding + "\" is not supported (raw, gzip)",
                           {file, "", ""});
  }

  LoadedVolume loaded;
  loaded.format = "NRRD";
  loaded.files = {path};
  fs::path data_path = path;
  std::uint64_t offset = header.data_offset;
  if (const auto data = header.fields.find("data file"); data != header.fields.end()) {
    data_path = path.parent_path() / data->second;
    offset = 0;
    if (!fs::is_regular_file(data_path)) {
      throw core::InputError("the data file " + data->second + " named by the header is missing",
                             {file, "", ""});
    }
    loaded.files.push_back(data_path);
  }
  if (const auto skip = header.fields.find("byte skip"); skip != header.fields.end()) {
    long bytes = 0;
    const char* first = skip->second.c_str();
    char* end = nullptr;
    errno = 0;
    bytes = std::strtol(first, &end, 10);
    if (end == first || *end != '\0' || errno == ERANGE) {
      throw core::InputError(
          "header field \"byte skip: " + skip->second + "\" is not a whole number", {file, "", ""});
    }
    if (bytes < 0) throw core::InputError("\"byte skip: -1\" is not supported", {file, "", ""});
    if (!gzip) offset += static_cast<std::uint64_t>(bytes);
  }
  const std::uint64_t count = static_cast<std::uint64_t>(dims[0] * dims[1] * dims[2]);
  std::string bytes = read_data(data_path, offset, count * sample.bytes, gzip, data_path.string());
  const auto endian = header.fields.find("endian");
  const bool swap = sample.bytes > 1 && endian != header.fields.end() &&
                    (endian->second == "big") == host_is_little_endian();
  if (swap) {
    for (std::uint64_t v = 0; v < count; ++v)
      std::reverse(bytes.begin() + v * sample.bytes, bytes.begin() + (v + 1) * sample.bytes);
  }

  core::ImageVolume& volume = loaded.volume;
  volume.dims = {static_cast<int>(dims[0]), static_cast<int>(dims[1]), static_cast<int>(dims[2])};
  volume.scalar_type = sample.type;
  volume.allocate();
  if (static_cast<int>(core::scalar_size(sample.type)) == sample.bytes) {
    std::memcpy(volume.voxels.data(), bytes.data(), volume.voxels.size());
  } else {  // int8 → int16, uint32 → float64
    for (std::uint64_t v = 0; v < count; ++v) {
      if (sample.bytes == 1) {
        const auto value = static_cast<std::int16_t>(static_cast<signed char>(bytes[v]));
        std::memcpy(volume.voxels.data() + 2 * v, &value, 2);
      } else {
        std::uint32_t raw;
        std::memcpy(&raw, bytes.data() + 4 * v, 4);
        const double value = raw;
        std::memcpy(volume.voxels.data() + 8 * v, &value, 8);
      }
    }
  }

  core::Mat3 axes = core::Mat3::Identity();
  bool ras = false;
  if (header.directions.size() == 3) {
    for (int c = 0; c < 3; ++c)
      axes.col(c) = header.directions[c];
    const auto space = header.fields.find("space");
    const std::string s = space == header.fields.end() ? "" : space->second;
    ras = s == "right-anterior-superior" || s == "RAS" || s == "scanner-xyz";
    if (!ras && s != "left-posterior-superior" && s != "LPS") {
      loaded.notes.push_back("space \"" + s + "\" taken as LPS");
    }
  } else {
    core::Vec3 step = core::Vec3::Ones();
    if (const auto spacings = header.fields.find("spacings"); spacings != header.fields.end()) {
      std::istringstream numbers(spacings->second);
      for (int a = 0; a < 3; ++a) {
        std::string word;
        numbers >> word;
        try {
          step[a] = std::stod(word);
        } catch (const std::exception&) {
          step[a] = 1.0;
        }
      }
    } else {
      loaded.notes.push_back("header gives no spacing; 1 mm assumed");
    }
    axes = step.asDiagonal();
    loaded.notes.push_back("header has no space directions; axes taken as aligned with the world");
  }
  set_geometry_mm(volume, axes, header.origin, ras, file);
  return loaded;
}

}  // namespace viscera::importers::detail
