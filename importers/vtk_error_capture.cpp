#include "importers/vtk_error_capture.h"

#include <vtkObject.h>

namespace viscera::importers {

VtkErrorCapture::VtkErrorCapture()
    : previous_(vtkOutputWindow::GetInstance()),
      display_(vtkObject::GetGlobalWarningDisplay()),
      stderr_verbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  previous_->Register(nullptr);
  capture_->SetDisplayModeToAlways();  // to the capture, not to vtkLogger on the terminal
  vtkOutputWindow::SetInstance(capture_);
  vtkObject::GlobalWarningDisplayOn();
}

VtkErrorCapture::~VtkErrorCapture() {
  vtkOutputWindow::SetInstance(previous_);
  previous_->UnRegister(nullptr);
  vtkObject::SetGlobalWarningDisplay(display_);
  vtkLogger::SetStderrVerbosity(stderr_verbosity_);
}

std::string VtkErrorCapture::first_error() {
  std::string text = capture_->GetOutput();
  const auto error = text.find("ERROR");
  if (error == std::string::npos) return {};
  text = text.substr(error);
  if (const auto at = text.find("): "); at != std::string::npos) text = text.substr(at + 3);
  if (const auto newline = text.find('\n'); newline != std::string::npos)
    text = text.substr(0, newline);
  return text.empty() ? "unknown error" : text;
}

}  // namespace viscera::importers
