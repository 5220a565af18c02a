#pragma once
/// Holds back the user's input while a background task reads the document (issue 21: during the
/// 400 ms before a task's progress dialog appears, an Undo could change the document under the
/// worker thread). While an InputBlocker lives, keyboard, mouse, wheel, drag-and-drop and
/// shortcut events to anything outside `allowed` (the task's dialog) are dropped, from the first
/// moment, whether the dialog is shown yet or not.

#include <QObject>

class QWidget;

namespace viscera::studio {

class InputBlocker : public QObject {
 public:
  /// Starts blocking; `allowed` (may be null) and its children still get their input.
  explicit InputBlocker(QWidget* allowed);
  ~InputBlocker() override;
  InputBlocker(const InputBlocker&) = delete;
  InputBlocker& operator=(const InputBlocker&) = delete;

  /// Input events dropped so far.
  int dropped() const { return dropped_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QWidget* allowed_;
  int dropped_ = 0;
};

}  // namespace viscera::studio
