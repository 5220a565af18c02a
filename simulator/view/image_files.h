#pragma once
/// Frames and plots as files: PNG encoding in memory and writes that never leave a partial file.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>

class vtkImageData;

namespace viscera::view {

/// The PNG bytes of an RGB or RGBA image (vtkPNGWriter, written to memory).
std::string encode_png(vtkImageData* image);

/// Writes `bytes` to `path` through a temporary sibling renamed into place (creating the
/// parent folder); throws core::OutputError naming `path`.
void write_file_atomically(const std::filesystem::path& path, const std::string& bytes);

}  // namespace viscera::view
