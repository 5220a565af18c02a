#pragma once
/// Catches what VTK readers report while Viscera reads a file, so a failure reaches the user
/// once, as a typed error naming the file, instead of pages of pipeline dumps. Internal to
/// viscera_importers.

#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkStringOutputWindow.h>

#include <string>

namespace viscera::importers {

/// The first error VTK reports anywhere while it lives (the reader or the parsers and streams it
/// creates), without its "ERROR: In <source>, line N" preamble; nothing reaches the terminal.
/// Global VTK state, like core::ScopedVtkSilence: not for concurrent use from several threads.
class VtkErrorCapture {
 public:
  VtkErrorCapture();
  ~VtkErrorCapture();
  VtkErrorCapture(const VtkErrorCapture&) = delete;
  VtkErrorCapture& operator=(const VtkErrorCapture&) = delete;

  /// The first error's message, or empty.
  std::string first_error();

 private:
  vtkNew<vtkStringOutputWindow> capture_;
  vtkOutputWindow* previous_;
  int display_;
  vtkLogger::Verbosity stderr_verbosity_;
};

}  // namespace viscera::importers
