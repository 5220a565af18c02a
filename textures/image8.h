#pragma once
/// 8-bit images as the texture pipeline passes them around: maps, samples and atlases. OpenCV
/// stays inside textures/ (png_io.cpp); callers see only this plain type.

#include <cstdint>
#include <vector>

namespace viscera::textures {

/// Row-major, channel-interleaved 8-bit image: 1 channel (grey) or 3 (RGB, sRGB values).
struct Image8 {
  int width = 0;
  int height = 0;
  int channels = 3;
  std::vector<std::uint8_t> pixels;  ///< width × height × channels

  Image8() = default;
  Image8(int w, int h, int c)
      : width(w), height(h), channels(c), pixels(static_cast<std::size_t>(w) * h * c, 0) {}

  bool empty() const { return pixels.empty(); }
  std::uint8_t* row(int y) {
    return pixels.data() + static_cast<std::size_t>(y) * width * channels;
  }
  const std::uint8_t* row(int y) const {
    return pixels.data() + static_cast<std::size_t>(y) * width * channels;
  }

  bool operator==(const Image8&) const = default;
};

}  // namespace viscera::textures
