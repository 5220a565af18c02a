#include "textures/png_io.h"

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <system_error>

#include "core/error.h"

namespace viscera::textures {
namespace {

Image8 from_mat(const cv::Mat& decoded) {
  cv::Mat converted;
  if (decoded.channels() == 1) {
    converted = decoded;
  } else if (decoded.channels() == 4) {
    cv::cvtColor(decoded, converted, cv::COLOR_BGRA2RGB);
  } else {
    cv::cvtColor(decoded, converted, cv::COLOR_BGR2RGB);
  }
  if (converted.depth() != CV_8U) converted.convertTo(converted, CV_8U, 1.0 / 257.0);
  Image8 image(converted.cols, converted.rows, converted.channels());
  for (int y = 0; y < image.height; ++y) {
    const auto* source = converted.ptr<std::uint8_t>(y);
    std::copy(source, source + static_cast<std::size_t>(image.width) * image.channels,
              image.row(y));
  }
  return image;
}

}  // namespace

Image8 read_image_rgb(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw core::InputError("no such image file", {path.string(), "", ""});
  }
  // IMREAD_COLOR decodes grey and palette images to three channels as well.
  const cv::Mat decoded = cv::imread(path.string(), cv::IMREAD_COLOR);
  if (decoded.empty()) {
    throw core::InputError("not an image OpenCV can decode", {path.string(), "", ""});
  }
  return from_mat(decoded);
}

Image8 decode_image(const std::string& bytes, const std::string& what) {
  const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
  const cv::Mat decoded = cv::imdecode(buffer, cv::IMREAD_UNCHANGED);
  if (decoded.empty()) throw core::InputError("not a decodable image", {what, "", ""});
  return from_mat(decoded);
}

std::string encode_png(const Image8& image) {
  if (image.empty() || (image.channels != 1 && image.channels != 3)) {
    throw core::OutputError("cannot encode an empty image or one with " +
                            std::to_string(image.channels) + " channels as PNG");
  }
  const cv::Mat rgb(image.height, image.width, image.channels == 1 ? CV_8UC1 : CV_8UC3,
                    const_cast<std::uint8_t*>(image.pixels.data()));
  cv::Mat bgr;
  if (image.channels == 3) {
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  } else {
    bgr = rgb;
  }
  std::vector<std::uint8_t> bytes;
  // Level 3: within a few percent of level 9's size at a fraction of its time; zlib is
  // deterministic, so the same pixels give the same bytes.
  if (!cv::imencode(".png", bgr, bytes, {cv::IMWRITE_PNG_COMPRESSION, 3})) {
    throw core::OutputError("PNG encoding failed");
  }
  return {bytes.begin(), bytes.end()};
}

void write_file_atomically(const std::string& bytes, const std::filesystem::path& path) {
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw core::OutputError("cannot open for writing", {path.string(), "", ""});
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw core::OutputError("write failed", {path.string(), "", ""});
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw core::OutputError("cannot rename into place: " + ec.message(), {path.string(), "", ""});
  }
}

void write_png(const Image8& image, const std::filesystem::path& path) {
  write_file_atomically(encode_png(image), path);
}

}  // namespace viscera::textures
