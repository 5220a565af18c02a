#include "studio/ui/input_blocker.h"

#include <QCoreApplication>
#include <QEvent>
#include <QWidget>
#include <QWindow>

namespace viscera::studio {
namespace {

bool is_user_input(QEvent::Type type) {
  switch (type) {
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
    case QEvent::ShortcutOverride:
    case QEvent::Shortcut:
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::Wheel:
    case QEvent::ContextMenu:
    case QEvent::DragEnter:
    case QEvent::DragMove:
    case QEvent::Drop:
    case QEvent::TouchBegin:
    case QEvent::TouchUpdate:
    case QEvent::TouchEnd:
      return true;
    default:
      return false;
  }
}

}  // namespace

InputBlocker::InputBlocker(QWidget* allowed) : allowed_(allowed) {
  QCoreApplication::instance()->installEventFilter(this);
}

InputBlocker::~InputBlocker() {
  QCoreApplication::instance()->removeEventFilter(this);
}

bool InputBlocker::eventFilter(QObject* watched, QEvent* event) {
  if (!is_user_input(event->type())) return false;
  if (allowed_ != nullptr) {
    if (const auto* widget = qobject_cast<QWidget*>(watched);
        widget != nullptr && (widget == allowed_ || allowed_->isAncestorOf(widget))) {
      return false;
    }
    if (const auto* window = qobject_cast<QWindow*>(watched);
        window != nullptr && allowed_->windowHandle() == window) {
      return false;
    }
  }
  ++dropped_;
  return true;
}

}  // namespace viscera::studio
