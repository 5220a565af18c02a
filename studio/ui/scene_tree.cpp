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
    const QString id = item->data(0, kObjectRole).toString();
    if (!id.isEmpty() && item->childCount() == 0) {
      emit visibility_changed(id, item->checkState(0) == Qt::Checked);
    }
  });
}

void SceneTree::show_scenario(const core::Scenario& scenario) {
  updating_ = true;
  QSet<QString> hidden;
  for (QTreeWidgetItemIterator it(this); *it != nullptr; ++it) {
    const QString id = (*it)->data(0, kObjectRole).toString();
    if (!id.isEmpty() && (*it)->childCount() == 0 && (*it)->checkState(0) == Qt::Unchecked) {
      hidden.insert(id);
    }
  }
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
      parent->setFlags(parent->flags() | Qt::ItemIsUserCheckable | Qt::ItemIsAutoTristate);
    }
    const QString details =
        q(core::to_string(object.role)) +
        (object.material.empty() ? QString() : QStringLiteral(", ") + q(object.material)) +
        (object.body.tets.empty() ? QString() : tr(", %1 tets").arg(object.body.tets.size()));
    auto* item =
        new QTreeWidgetItem(parent, {q(object.name.empty() ? object.id : object.name), details});
    const QString id = q(object.id);
    item->setData(0, kObjectRole, id);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(0, hidden.contains(id) ? Qt::Unchecked : Qt::Checked);
  }

  auto* vessels = new QTreeWidgetItem(
      this, {tr("Vessel trees"), QString::number(scenario.vessel_trees.size())});
  for (const auto& tree : scenario.vessel_trees) {
    auto* item = new QTreeWidgetItem(vessels, {q(tree.id), tr("%1, %2 segments in %3")
                                                               .arg(q(tree.kind))
                                                               .arg(tree.segments.size())
                                                               .arg(q(tree.host_object))});
    item->setData(0, kObjectRole, q(tree.host_object));
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
  expandAll();
  updating_ = false;
  select_object(selected_id);
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
