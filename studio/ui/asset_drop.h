#pragma once
/// Drops of library entries (issue 9 §7) onto the 3D view and the scene tree: an event filter
/// that accepts drags carrying kAssetMimeType (library_browser.h) and hands the drop, with the
/// object under the cursor, to the main window. Tests send constructed QDropEvents through the
/// same filter.

#include <QObject>
#include <QPoint>
#include <QString>
#include <functional>

class QMimeData;
class QWidget;

namespace viscera::studio {

class AssetDropFilter : public QObject {
  Q_OBJECT

 public:
  /// The object id under a position of the watched widget ("" for none).
  using TargetAt = std::function<QString(const QPoint&)>;
  /// Handles a drop; returns whether it was used.
  using Drop = std::function<bool(const QMimeData*, const QString& target)>;

  /// Watches `widget` (and lets it accept drops); the filter is owned by the widget.
  AssetDropFilter(QWidget* widget, TargetAt target_at, Drop drop);

  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  TargetAt target_at_;
  Drop drop_;
};

}  // namespace viscera::studio
