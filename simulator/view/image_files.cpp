#include "simulator/view/image_files.h"

#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>

#include <fstream>
#include <system_error>

#include "core/error.h"

namespace viscera::view {

std::string encode_png(vtkImageData* image) {
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* result = writer->GetResult();
  if (result == nullptr || result->GetNumberOfTuples() == 0)
    throw core::OutputError("PNG encoding produced no bytes");
  return std::string(reinterpret_cast<const char*>(result->GetPointer(0)),
                     static_cast<std::size_t>(result->GetNumberOfTuples()));
}

void write_file_atomically(const std::filesystem::path& path, const std::string& bytes) {
  std::error_code error;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), error);
  if (error) throw core::OutputError("cannot create the folder", {path.string(), "", ""});
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::filesystem::remove(temporary, error);
      throw core::OutputError("cannot write", {path.string(), "", ""});
    }
  }
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw core::OutputError("cannot move the finished file into place", {path.string(), "", ""});
  }
}

}  // namespace viscera::view
