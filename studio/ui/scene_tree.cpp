#include "studio/ui/scene_tree.h"

#include <QHeaderView>
#include <QSet>
#include <map>

namespace viscera::studio {
namespace {

QString q(const std::string& text) {
  return QString::fromStdString(text);
}

QString role_heading(core::ObjectRole role) {
  switch (role) {
    case core::ObjectRole::Organ:
      return QObject::tr("Organs");
    case core::ObjectRole::Pathology:
      return QObject::tr("Pathology objects");
    case core::ObjectRole::Vessel:
      return QObject::tr("Vessel objects");
    case core::ObjectRole::Fixture:
      return QObject::tr("Fixtures");
    case core::ObjectRole::Instrument:
      return QObject::tr("Instruments");
  }
  return QObject::tr("Objects");
}

}  // namespace

SceneTree::SceneTree(QWidget* parent) : QTreeWidget(parent) {
  setColumnCount(2);
  setHeaderLabels({tr("Scene"), tr("Details")});
  header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  setSelectionMode(QAbstractItemView::SingleSelection);
  connect(this, &QTreeWidget::itemSelectionChanged, this, [this] {
    if (updating_) return;
    const auto items = selectedItems();
    emit object_selected(items.isEmpty() ? QString() : items[0]->data(0, kObjectRole).toString());
  });
  connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
    if (updating_ || column != 0) return;
    const bool visible = item->checkState(0) != Qt::Unchecked;
    QStringList keys;
    const QString key = item->data(0, kVisibilityRole).toString();
    if (!key.isEmpty()) {
      keys << key;
    } else if (item->data(0, kGroupRole).toBool()) {
      for (int c = 0; c < item->childCount(); ++c) {
        const QString child = item->child(c)->data(0, kVisibilityRole).toString();
        if (!child.isEmpty()) keys << child;
      }
    }
    if (keys.isEmpty()) return;
    // The box shows the document, not the click: put it back until the document changes.
    updating_ = true;
    item->setCheckState(0, visible ? Qt::Unchecked : Qt::Checked);
    updating_ = false;
    emit visibility_changed(keys, visible);
  });
}

void SceneTree::show_scenario(const core::Scenario& scenario, const ViewState& state) {
  updating_ = true;
  const auto selected = selectedItems();
  const QString selected_id =
      selected.isEmpty() ? QString() : selected[0]->data(0, kObjectRole).toString();
  clear();

  auto* objects =
      new QTreeWidgetItem(this, {tr("Objects"), QString::number(scenario.objects.size())});
  std::map<QString, QTreeWidgetItem*> folders;
  for (const auto& object : scenario.objects) {
    const QString folder = object.group.empty() ? role_heading(object.role) : q(object.group);
    auto& parent = folders[folder];
    if (parent == nullptr) {
      parent = new QTreeWidgetItem(objects, {folder});
      parent->setData(0, kGroupRole, true);
    }
    const QString details =
        q(core::to_string(object.role)) +
        (object.material.empty() ? QString() : QStringLiteral(", ") + q(object.material)) +
        (object.body.tets.empty() ? QString() : tr(", %1 tets").arg(object.body.tets.size()));
    auto* item =
        new QTreeWidgetItem(parent, {q(object.name.empty() ? object.id : object.name), details});
    const QString id = q(object.id);
    item->setData(0, kObjectRole, id);
    item->setData(0, kVisibilityRole, id);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(0, state.visible(object.id) ? Qt::Checked : Qt::Unchecked);
  }

  auto* vessels = new QTreeWidgetItem(
      this, {tr("Vessel trees"), QString::number(scenario.vessel_trees.size())});
  vessels->setData(0, kGroupRole, !scenario.vessel_trees.empty());
  for (const auto& tree : scenario.vessel_trees) {
    auto* item = new QTreeWidgetItem(vessels, {q(tree.id), tr("%1, %2 segments in %3")
                                                               .arg(q(tree.kind))
                                                               .arg(tree.segments.size())
                                                               .arg(q(tree.host_object))});
    item->setData(0, kObjectRole, q(tree.host_object));
    item->setData(0, kVisibilityRole, q(vessel_tree_key(tree.id)));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(0, state.visible(vessel_tree_key(tree.id)) ? Qt::Checked : Qt::Unchecked);
  }
  auto* pathologies =
      new QTreeWidgetItem(this, {tr("Pathologies"), QString::number(scenario.pathologies.size())});
  for (const auto& pathology : scenario.pathologies) {
    auto* item = new QTreeWidgetItem(pathologies,
                                     {q(pathology.id), tr("%1, %2 mm in %3")
                                                           .arg(q(pathology.kind))
                                                           .arg(pathology.size * 1000.0, 0, 'f', 1)
                                                           .arg(q(pathology.host_object))});
    item->setData(0, kObjectRole,
                  q(pathology.object.empty() ? pathology.host_object : pathology.object));
  }
  volume_item_ = nullptr;
  expandAll();
  update_group_boxes();
  updating_ = false;
  show_image_volume(volume_present_, volume_shown_);
  select_object(selected_id);
}

void SceneTree::apply_view_state(const ViewState& state) {
  updating_ = true;
  for (QTreeWidgetItemIterator it(this); *it != nullptr; ++it) {
    const QString key = (*it)->data(0, kVisibilityRole).toString();
    if (key.isEmpty() || *it == volume_item_) continue;
    (*it)->setCheckState(0, state.visible(key.toStdString()) ? Qt::Checked : Qt::Unchecked);
  }
  update_group_boxes();
  updating_ = false;
}

void SceneTree::update_group_boxes() {
  for (QTreeWidgetItemIterator it(this); *it != nullptr; ++it) {
    QTreeWidgetItem* group = *it;
    if (!group->data(0, kGroupRole).toBool() || group->childCount() == 0) continue;
    int shown = 0;
    for (int c = 0; c < group->childCount(); ++c)
      shown += group->child(c)->checkState(0) == Qt::Checked ? 1 : 0;
    group->setCheckState(0, shown == group->childCount() ? Qt::Checked
                            : shown == 0                 ? Qt::Unchecked
                                                         : Qt::PartiallyChecked);
  }
}

void SceneTree::show_image_volume(bool present, bool shown) {
  const bool was = updating_;
  updating_ = true;
  volume_present_ = present;
  volume_shown_ = shown;
  if (!present) {
    delete volume_item_;
    volume_item_ = nullptr;
  } else {
    if (volume_item_ == nullptr) {
      volume_item_ = new QTreeWidgetItem(this, {tr("Image volume"), tr("slice planes")});
      volume_item_->setData(0, kVisibilityRole, kImageVolumeKey);
      volume_item_->setFlags(volume_item_->flags() | Qt::ItemIsUserCheckable);
    }
    volume_item_->setCheckState(0, shown ? Qt::Checked : Qt::Unchecked);
  }
  updating_ = was;
}

QTreeWidgetItem* SceneTree::visibility_item(const QString& key) const {
  for (QTreeWidgetItemIterator it(const_cast<SceneTree*>(this)); *it != nullptr; ++it) {
    if ((*it)->data(0, kVisibilityRole).toString() == key) return *it;
  }
  return nullptr;
}

QTreeWidgetItem* SceneTree::object_item(const QString& id) const {
  if (id.isEmpty()) return nullptr;
  for (QTreeWidgetItemIterator it(const_cast<SceneTree*>(this)); *it != nullptr; ++it) {
    if ((*it)->data(0, kObjectRole).toString() == id && (*it)->flags() & Qt::ItemIsUserCheckable) {
      return *it;
    }
  }
  return nullptr;
}

void SceneTree::select_object(const QString& id) {
  updating_ = true;
  clearSelection();
  if (QTreeWidgetItem* item = object_item(id)) {
    item->setSelected(true);
    scrollToItem(item);
  }
  updating_ = false;
}

}  // namespace viscera::studio
