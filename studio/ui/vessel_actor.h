#pragma once
/// A vessel tree drawn in the studio's 3D view: every segment a tube of its own radius
/// (vtkTubeFilter on the centre lines), in arterial red or venous blue.

#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include "core/scenario/scenario_parts.h"

namespace viscera::studio {

/// The tree's tubes as one unpickable actor, or null for a tree without segments.
vtkSmartPointer<vtkActor> vessel_tree_actor(const core::VesselTree& tree);

}  // namespace viscera::studio
