// INRIMAGE-4 (.inr, .inr.gz) through CGAL Image_3 (CGAL_ImageIO), the format of CGAL's own
// image data. The text header (multiples of 256 bytes, "#INRIMAGE-4#{" … "##}") is read here
// first, through zlib so .gz files need no temporary copy, to check the memory limit and the
// file's length before CGAL allocates; CGAL then reads and byte-swaps the voxels. INRIMAGE
// has spacing (VX/VY/VZ) and translation (TX/TY/TZ, CGAL 5.5 fields) but no orientation.
#include <CGAL/Image_3.h>
#include <zlib.h>

#include <cstring>
#include <map>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "importers/volume/format_readers.h"
#include "importers/volume/volume_geometry.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

struct GzFile {
  gzFile handle;
  explicit GzFile(const std::string& file) : handle(gzopen(file.c_str(), "rb")) {}
  ~GzFile() {
    if (handle != nullptr) gzclose(handle);
  }
  GzFile(const GzFile&) = delete;
  GzFile& operator=(const GzFile&) = delete;
};

/// The header's KEY=value lines; throws naming the file when the magic or end is missing.
std::map<std::string, std::string> read_header(GzFile& in, const std::string& file,
                                               std::size_t& header_bytes) {
  std::string text;
  char block[256];
  while (text.find("##}") == std::string::npos) {
    const int got = gzread(in.handle, block, sizeof block);
    if (got != static_cast<int>(sizeof block) || text.size() > 64 * 256) {
      throw core::InputError(text.empty() ? "not an INRIMAGE file (no 256-byte header)"
                                          : "INRIMAGE header has no end (\"##}\")",
                             {file, "", ""});
    }
    text.append(block, sizeof block);
    if (text.rfind("#INRIMAGE-4#{", 0) != 0) {
      throw core::InputError("not an INRIMAGE-4 file (no #INRIMAGE-4#{ magic)", {file, "", ""});
    }
  }
  header_bytes = text.size();
  std::map<std::string, std::string> fields;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto equals = line.find('=');
    if (equals != std::string::npos) fields[line.substr(0, equals)] = line.substr(equals + 1);
  }
  return fields;
}

double number(const std::map<std::string, std::string>& fields, const std::string& key,
              double fallback, const std::string& file) {
  const auto it = fields.find(key);
  if (it == fields.end()) return fallback;
  try {
    return std::stod(it->second);
  } catch (const std::exception&) {
    throw core::InputError("header field " + key + "=" + it->second + " is not a number",
                           {file, "", ""});
  }
}

template <typename From, typename To>
void convert(const void* data, std::size_t count, core::ImageVolume& out) {
  const auto* source = static_cast<const From*>(data);
  auto* target = reinterpret_cast<To*>(out.voxels.data());
  for (std::size_t v = 0; v < count; ++v)
    target[v] = static_cast<To>(source[v]);
}

}  // namespace

LoadedVolume read_inr(const fs::path& path, const VolumeReadOptions& options) {
  const std::string file = path.string();
  std::int64_t dims[3], components, bytes;
  {
    GzFile in(file);
    if (in.handle == nullptr) throw core::InputError("cannot open the file", {file, "", ""});
    std::size_t header_bytes = 0;
    const auto fields = read_header(in, file, header_bytes);
    dims[0] = static_cast<std::int64_t>(number(fields, "XDIM", 0, file));
    dims[1] = static_cast<std::int64_t>(number(fields, "YDIM", 0, file));
    dims[2] = static_cast<std::int64_t>(number(fields, "ZDIM", 1, file));
    components = static_cast<std::int64_t>(number(fields, "VDIM", 1, file));
    bytes = static_cast<std::int64_t>(number(fields, "PIXSIZE", 8, file)) / 8;
    const auto pixsize = fields.find("PIXSIZE");
    if (pixsize != fields.end() && pixsize->second.find("bits") == std::string::npos) {
      throw core::InputError("header field PIXSIZE=" + pixsize->second + " gives no bit count",
                             {file, "", ""});
    }
    check_voxel_budget({dims[0], dims[1], dims[2]}, components, bytes, options, file);
    // Count the voxel bytes that follow the header (decompressing .gz as it goes).
    const long double needed =
        static_cast<long double>(dims[0]) * dims[1] * dims[2] * components * bytes;
    long double have = 0;
    std::vector<char> buffer(1 << 20);
    for (int got; have < needed && (got = gzread(in.handle, buffer.data(), buffer.size())) > 0;) {
      have += got;
    }
    if (have < needed) {
      throw core::InputError("file is truncated: the header asks for " +
                                 std::to_string(static_cast<unsigned long long>(needed)) +
                                 " bytes of voxels, the file holds " +
                                 std::to_string(static_cast<unsigned long long>(have)),
                             {file, "", ""});
    }
  }

  CGAL::Image_3 image;
  if (!image.read(file))
    throw core::InputError("CGAL ImageIO cannot read the file", {file, "", ""});
  const _image* im = image.image();
  LoadedVolume loaded;
  loaded.format = "INRIMAGE";
  loaded.files = {path};
  core::ImageVolume& volume = loaded.volume;
  volume.dims = {static_cast<int>(im->xdim), static_cast<int>(im->ydim),
                 static_cast<int>(im->zdim)};
  if (im->vdim != 1) {
    throw core::InputError("voxels have " + std::to_string(im->vdim) + " components; one is needed",
                           {file, "", ""});
  }
  const std::size_t count = volume.voxel_count();
  const bool is_float = im->wordKind == WK_FLOAT;
  const bool is_signed = im->sign == SGN_SIGNED;
  const std::string kind = std::string(is_float    ? "float"
                                       : is_signed ? "signed"
                                                   : "unsigned") +
                           " " + std::to_string(8 * im->wdim) + "-bit";
  if (is_float && im->wdim == 4) {
    volume.scalar_type = core::ScalarType::Float32;
    volume.allocate();
    convert<float, float>(im->data, count, volume);
  } else if (is_float && im->wdim == 8) {
    volume.scalar_type = core::ScalarType::Float64;
    volume.allocate();
    convert<double, double>(im->data, count, volume);
  } else if (!is_float && im->wdim == 1) {
    volume.scalar_type = is_signed ? core::ScalarType::Int16 : core::ScalarType::UInt8;
    volume.allocate();
    if (is_signed)
      convert<std::int8_t, std::int16_t>(im->data, count, volume);
    else
      convert<std::uint8_t, std::uint8_t>(im->data, count, volume);
  } else if (!is_float && im->wdim == 2) {
    volume.scalar_type = is_signed ? core::ScalarType::Int16 : core::ScalarType::UInt16;
    volume.allocate();
    std::memcpy(volume.voxels.data(), im->data, volume.voxels.size());
  } else if (!is_float && im->wdim == 4) {
    volume.scalar_type = is_signed ? core::ScalarType::Int32 : core::ScalarType::Float64;
    volume.allocate();
    if (is_signed)
      convert<std::int32_t, std::int32_t>(im->data, count, volume);
    else
      convert<std::uint32_t, double>(im->data, count, volume);
  } else {
    throw core::InputError("unsupported voxel type " + kind, {file, "", ""});
  }
  const core::Vec3 step(im->vx, im->vy, im->vz);
  set_geometry_mm(volume, step.asDiagonal(), core::Vec3(im->tx, im->ty, im->tz), false, file);
  return loaded;
}

}  // namespace viscera::importers::detail
