#pragma once
/// A VTK image read that never runs in this process. Some damaged files corrupt the heap inside
/// a library without crashing at once (the volume_metaimage fuzz target: vtkmetaio overwrote
/// the heap's bookkeeping; the guard's child survived it and the parent's own read then
/// corrupted the parent), so a guard that only asks "did the child survive?" (crash_guard.h) is
/// not enough for such a reader. Here the child does the whole read and sends the voxels back
/// through a pipe; the parent only rebuilds the image from plain numbers it checks first.
/// Internal to viscera_importers.
///
/// Cost: one fork and one copy of the voxels through the pipe, instead of the read done twice.

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <string>

#include "core/crash_guard.h"

namespace viscera::importers::detail {

/// Runs `read` in a forked child (core::prepare_guard_child(memory_bytes), ended after
/// core::kGuardSeconds) and returns a copy of the image it returned: dimensions, spacing, origin
/// and scalars (type and components). `read` may throw core::Error or any std::exception to
/// refuse the file: its reason comes back. Throws core::InputError naming `file`: the child's
/// refusal, or "`reader` crashes, hangs or exhausts its memory on it" when a signal or the alarm
/// ended the child; core::Error when no child can be started.
vtkSmartPointer<vtkImageData> read_image_in_child(
    const std::function<vtkImageData*()>& read, const std::string& file, const std::string& reader,
    std::uint64_t memory_bytes = core::kGuardMemoryBytes);

}  // namespace viscera::importers::detail
