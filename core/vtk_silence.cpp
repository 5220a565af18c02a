#include "core/vtk_silence.h"

#include <vtkObject.h>

namespace viscera::core {

ScopedVtkSilence::ScopedVtkSilence() : previous_(vtkObject::GetGlobalWarningDisplay()) {
  vtkObject::GlobalWarningDisplayOff();
}

ScopedVtkSilence::~ScopedVtkSilence() {
  vtkObject::SetGlobalWarningDisplay(previous_);
}

}  // namespace viscera::core
