#include "studio/ui/organ_panel.h"

#include "core/error.h"
#include "studio/ui/background_task.h"

namespace viscera::studio {

OrganPanel::OrganPanel(ScenarioDocument& document, QWidget* parent)
    : QWidget(parent), document_(document) {
  connect(&document_, &ScenarioDocument::changed, this, [this] {
    if (!object_id_.isEmpty() &&
        document_.scenario().find_object(object_id_.toStdString()) == nullptr)
      object_id_.clear();
    refresh();
  });
}

void OrganPanel::show_object(const QString& id) {
  object_id_ = id;
  refresh();
}

std::string OrganPanel::require_object() {
  if (object_id_.isEmpty() ||
      document_.scenario().find_object(object_id_.toStdString()) == nullptr) {
    emit failed(tr("Select an object first."));
    return {};
  }
  return object_id_.toStdString();
}

bool OrganPanel::run(const QString& title, const std::function<void(core::Progress&)>& work) {
  const std::exception_ptr error = run_in_background(this, title, work);
  if (!error) return true;
  try {
    std::rethrow_exception(error);
  } catch (const core::CancelledError&) {
    return false;
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
  }
  return false;
}

bool OrganPanel::push(const std::function<QUndoCommand*()>& make) {
  try {
    document_.undo_stack()->push(make());
    return true;
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return false;
  }
}

}  // namespace viscera::studio
