#include "studio/ui/asset_drop.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QWidget>

#include "studio/ui/library_browser.h"

namespace viscera::studio {

AssetDropFilter::AssetDropFilter(QWidget* widget, TargetAt target_at, Drop drop)
    : QObject(widget), target_at_(std::move(target_at)), drop_(std::move(drop)) {
  widget->setAcceptDrops(true);
  widget->installEventFilter(this);
}

bool AssetDropFilter::eventFilter(QObject* watched, QEvent* event) {
  switch (event->type()) {
    case QEvent::DragEnter:
    case QEvent::DragMove: {
      auto* drag = static_cast<QDragMoveEvent*>(event);
      if (!asset_from_mime(drag->mimeData())) return false;
      drag->setDropAction(Qt::CopyAction);
      drag->accept();
      return true;
    }
    case QEvent::Drop: {
      auto* drop = static_cast<QDropEvent*>(event);
      if (!asset_from_mime(drop->mimeData())) return false;
      const bool used = drop_(drop->mimeData(), target_at_(drop->pos()));
      drop->setDropAction(Qt::CopyAction);
      if (used) {
        drop->accept();
      } else {
        drop->ignore();
      }
      return true;
    }
    default:
      return QObject::eventFilter(watched, event);
  }
}

}  // namespace viscera::studio
