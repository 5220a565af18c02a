#pragma once
/// The error of a file that could hold tetrahedra but holds none.

#include "core/error.h"

namespace viscera::importers {

/// A file that could hold tetrahedra holds none (a surface-only .msh or .vtk); callers that
/// accept either kind of mesh catch it and read the surface instead.
class NoTetrahedraError : public core::InputError {
 public:
  using core::InputError::InputError;
};

}  // namespace viscera::importers
