#pragma once
/// Long work off the UI thread (issue 9 §9): a function taking a core::Progress runs on a worker
/// thread while a modal progress dialog shows its stage and fraction; Cancel asks the work to
/// stop through Progress::cancel(), and the work ends with core::CancelledError at its next step.

#include <QString>
#include <exception>
#include <functional>

#include "core/progress.h"

class QWidget;

namespace viscera::studio {

/// Runs `work` on a worker thread and returns once it ended, processing events meanwhile (the
/// dialog appears after `show_after_ms`; the user's input to anything but the dialog is dropped
/// from the start, InputBlocker). Returns the exception the work threw, or nullptr.
std::exception_ptr run_in_background(QWidget* parent, const QString& title,
                                     const std::function<void(core::Progress&)>& work,
                                     int show_after_ms = 400);

}  // namespace viscera::studio
