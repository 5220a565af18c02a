#pragma once
/// What the organ panels (texture, vessels, pathologies) share: the document, the object the
/// selection shows, background work with a progress dialog, and one-line errors.

#include <QUndoCommand>
#include <QWidget>
#include <functional>

#include "core/progress.h"
#include "studio/document/scenario_document.h"

namespace viscera::studio {

class OrganPanel : public QWidget {
  Q_OBJECT

 public:
  OrganPanel(ScenarioDocument& document, QWidget* parent = nullptr);

  /// The object the panel works on (empty: none; the panel's actions refuse).
  virtual void show_object(const QString& id);
  QString object_id() const { return object_id_; }

 signals:
  /// An action failed; the message is one sentence (the main window shows it).
  void failed(const QString& message);

 protected:
  /// The shown object's id, or emits failed() and returns empty when none is shown.
  std::string require_object();
  /// Runs `work` off the UI thread with a progress dialog; emits failed() for an error (a
  /// cancellation only returns false).
  bool run(const QString& title, const std::function<void(core::Progress&)>& work);
  /// Pushes the command `make` builds; emits failed() when building it throws.
  bool push(const std::function<QUndoCommand*()>& make);
  /// Called after the shown object changed or the document did.
  virtual void refresh() {}

  ScenarioDocument& document_;

 private:
  QString object_id_;
};

}  // namespace viscera::studio
