#pragma once
/// The scene tree (issue 9 §3): objects under their organ groups (objects without a group under
/// their role), vessel trees and pathologies. Objects, vessel trees and the image volume have a
/// visibility check box that shows the document's view state (view_state.h); ticking one asks
/// for a change (visibility_changed) and the box follows once the document has it, so the tree
/// and the 3D view cannot disagree (issue 23 §4). A group's box shows and hides its objects.
/// Selecting an item selects its object; select_object() follows picking in the 3D view.

#include <QTreeWidget>

#include "core/scenario/scenario.h"
#include "studio/document/view_state.h"

namespace viscera::studio {

class SceneTree : public QTreeWidget {
  Q_OBJECT

 public:
  explicit SceneTree(QWidget* parent = nullptr);

  /// Rebuilds the items with the boxes of `state`; keeps the selection of an id that remains.
  void show_scenario(const core::Scenario& scenario, const ViewState& state);
  /// Sets every box to `state` without emitting visibility_changed().
  void apply_view_state(const ViewState& state);
  /// Lists the image volume (the slice planes and volume rendering) with a box, or removes it.
  void show_image_volume(bool present, bool shown);
  /// The item with visibility key `key` (an object id, vessel_tree_key(), kImageVolumeKey).
  QTreeWidgetItem* visibility_item(const QString& key) const;
  /// Selects the item of object `id` (empty: clears) without emitting object_selected().
  void select_object(const QString& id);
  /// The item of object `id`, or null.
  QTreeWidgetItem* object_item(const QString& id) const;

  /// Item data role holding the object id an item stands for.
  static constexpr int kObjectRole = Qt::UserRole + 1;
  /// Item data role holding the visibility key of a box.
  static constexpr int kVisibilityRole = Qt::UserRole + 2;
  /// Item data role marking a group whose box shows and hides its children's.
  static constexpr int kGroupRole = Qt::UserRole + 3;
  /// Visibility key of the image volume's item.
  static inline const QString kImageVolumeKey = QStringLiteral("image-volume");

 signals:
  void object_selected(const QString& id);
  /// The user ticked or unticked boxes standing for `keys`.
  void visibility_changed(const QStringList& keys, bool visible);

 private:
  void update_group_boxes();

  bool updating_ = false;
  QTreeWidgetItem* volume_item_ = nullptr;
  bool volume_present_ = false, volume_shown_ = false;
};

}  // namespace viscera::studio
