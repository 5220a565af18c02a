#pragma once
/// Reading sample images and writing texture maps (PNG through OpenCV).

#include <filesystem>
#include <string>

#include "textures/image8.h"

namespace viscera::textures {

/// Reads any image OpenCV decodes (PNG, JPEG, BMP, TIFF, …) as 8-bit RGB. Throws
/// core::InputError naming the file when it cannot be read or holds no pixels.
Image8 read_image_rgb(const std::filesystem::path& path);

/// PNG bytes of `image` (1 or 3 channels). The same image gives the same bytes.
/// Throws core::OutputError if encoding fails.
std::string encode_png(const Image8& image);

/// Decodes PNG (or any OpenCV format) bytes to 8-bit RGB or grey as stored; `what` names the
/// source in errors (core::InputError).
Image8 decode_image(const std::string& bytes, const std::string& what);

/// Writes `bytes` to `path` through a temporary sibling renamed into place, so a failure leaves
/// nothing behind. Throws core::OutputError naming the file.
void write_file_atomically(const std::string& bytes, const std::filesystem::path& path);

/// encode_png + write_file_atomically.
void write_png(const Image8& image, const std::filesystem::path& path);

}  // namespace viscera::textures
