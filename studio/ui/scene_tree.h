#pragma once
/// The scene tree (issue 9 §3): objects under their organ groups (objects without a group under
/// their role), vessel trees and pathologies, each with a visibility check box. Selecting an
/// item selects its object; select_object() follows picking in the 3D view.

#include <QTreeWidget>

#include "core/scenario/scenario.h"

namespace viscera::studio {

class SceneTree : public QTreeWidget {
  Q_OBJECT

 public:
  explicit SceneTree(QWidget* parent = nullptr);

  /// Rebuilds the items; keeps check states and the selection of ids that remain.
  void show_scenario(const core::Scenario& scenario);
  /// Selects the item of object `id` (empty: clears) without emitting object_selected().
  void select_object(const QString& id);
  /// The item of object `id`, or null.
  QTreeWidgetItem* object_item(const QString& id) const;

  /// Item data role holding the object id an item stands for.
  static constexpr int kObjectRole = Qt::UserRole + 1;

 signals:
  void object_selected(const QString& id);
  void visibility_changed(const QString& id, bool visible);

 private:
  bool updating_ = false;
};

}  // namespace viscera::studio
