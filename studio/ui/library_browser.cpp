#include "studio/ui/library_browser.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QPushButton>
#include <QVBoxLayout>
#include <nlohmann/json.hpp>

#include "core/json_numbers.h"

namespace viscera::studio {
namespace {

/// A list whose drags carry the library entry.
class AssetList : public QListWidget {
 public:
  AssetList(LibraryBrowser* browser) : QListWidget(browser), browser_(browser) {}

 protected:
  QStringList mimeTypes() const override { return {QString::fromLatin1(kAssetMimeType)}; }
  QMimeData* mimeData(const QList<QListWidgetItem*> items) const override {
    if (items.isEmpty()) return nullptr;
    return asset_mime_data(browser_->library_path(), browser_->summary(row(items.first())));
  }

 private:
  LibraryBrowser* browser_;
};

}  // namespace

QMimeData* asset_mime_data(const std::filesystem::path& library,
                           const core::AssetSummary& summary) {
  auto* mime = new QMimeData;
  const nlohmann::json json = {{"library", std::filesystem::absolute(library).string()},
                               {"name", summary.name},
                               {"version", summary.version},
                               {"type", core::to_string(summary.type)}};
  mime->setData(QString::fromLatin1(kAssetMimeType), QByteArray::fromStdString(json.dump()));
  mime->setText(QString::fromStdString(summary.name));
  return mime;
}

std::optional<AssetReference> asset_from_mime(const QMimeData* mime) {
  if (mime == nullptr || !mime->hasFormat(QString::fromLatin1(kAssetMimeType))) return std::nullopt;
  const auto json = nlohmann::json::parse(
      mime->data(QString::fromLatin1(kAssetMimeType)).toStdString(), nullptr, false);
  try {
    AssetReference ref;
    ref.library = json.at("library").get<std::string>();
    ref.name = json.at("name").get<std::string>();
    ref.version = core::whole_number<int>(json.at("version"), "", "/version");
    ref.type = core::asset_type_from_string(json.at("type").get<std::string>());
    return ref;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

LibraryBrowser::LibraryBrowser(std::filesystem::path path, QWidget* parent)
    : QWidget(parent), path_(std::move(path)) {
  type_ = new QComboBox(this);
  type_->addItem(tr("All types"), -1);
  for (const auto type : {core::AssetType::Model, core::AssetType::Material,
                          core::AssetType::Texture, core::AssetType::Template})
    type_->addItem(QString::fromStdString(core::to_string(type)), static_cast<int>(type));
  search_ = new QLineEdit(this);
  search_->setPlaceholderText(tr("Search names and tags"));
  search_->setClearButtonEnabled(true);
  list_ = new AssetList(this);
  list_->setViewMode(QListView::IconMode);
  list_->setIconSize(QSize(96, 96));
  list_->setResizeMode(QListView::Adjust);
  list_->setMovement(QListView::Static);
  list_->setDragEnabled(true);
  list_->setDragDropMode(QAbstractItemView::DragOnly);
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  auto* add_object = new QPushButton(tr("Add object"), this);
  add_object->setToolTip(tr("Add the selected scene object to the library"));
  auto* add_material = new QPushButton(tr("Add material"), this);
  add_material->setToolTip(tr("Add the selected object's material to the library"));
  auto* refresh_button = new QPushButton(tr("Refresh"), this);

  auto* filters = new QHBoxLayout;
  filters->addWidget(type_);
  filters->addWidget(search_, 1);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(add_object);
  buttons->addWidget(add_material);
  buttons->addWidget(refresh_button);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addLayout(filters);
  layout->addWidget(list_, 1);
  layout->addWidget(status_);
  layout->addLayout(buttons);

  connect(type_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] { show_entries(); });
  connect(search_, &QLineEdit::textChanged, this, [this] { show_entries(); });
  connect(add_object, &QPushButton::clicked, this, &LibraryBrowser::add_object_requested);
  connect(add_material, &QPushButton::clicked, this, &LibraryBrowser::add_material_requested);
  connect(refresh_button, &QPushButton::clicked, this, &LibraryBrowser::refresh);
  refresh();
}

void LibraryBrowser::refresh() {
  entries_.clear();
  if (!std::filesystem::exists(path_)) {
    // Listing never creates a library; adding the first entry does.
    status_->setText(tr("No library yet at %1; adding an entry creates it.")
                         .arg(QString::fromStdString(path_.string())));
    show_entries();
    return;
  }
  try {
    const core::AssetLibrary library(path_);
    entries_ = library.list();
    status_->setText(
        tr("%1 entries in %2").arg(entries_.size()).arg(QString::fromStdString(path_.string())));
  } catch (const std::exception& e) {
    status_->setText(QString::fromUtf8(e.what()));
  }
  show_entries();
}

void LibraryBrowser::set_type_filter(std::optional<core::AssetType> type) {
  type_->setCurrentIndex(type ? type_->findData(static_cast<int>(*type)) : 0);
}

void LibraryBrowser::set_search(const QString& text) {
  search_->setText(text);
}

QStringList LibraryBrowser::shown_names() const {
  QStringList names;
  for (const auto& s : shown_)
    names << QString::fromStdString(s.name);
  return names;
}

const core::AssetSummary& LibraryBrowser::summary(int row) const {
  return shown_.at(static_cast<std::size_t>(row));
}

void LibraryBrowser::show_entries() {
  const int type = type_->currentData().toInt();
  const QString needle = search_->text().trimmed();
  shown_.clear();
  list_->clear();
  std::optional<core::AssetLibrary> library;
  try {
    if (!entries_.empty()) library.emplace(path_);
  } catch (const std::exception&) {
  }
  for (const auto& s : entries_) {
    if (type >= 0 && static_cast<int>(s.type) != type) continue;
    bool match =
        needle.isEmpty() || QString::fromStdString(s.name).contains(needle, Qt::CaseInsensitive);
    for (const auto& tag : s.tags)
      match = match || QString::fromStdString(tag).contains(needle, Qt::CaseInsensitive);
    if (!match) continue;
    shown_.push_back(s);
    auto* item = new QListWidgetItem(QString::fromStdString(s.name), list_);
    item->setToolTip(tr("%1 v%2 (%3, .%4)")
                         .arg(QString::fromStdString(s.name))
                         .arg(s.version)
                         .arg(QString::fromStdString(core::to_string(s.type)))
                         .arg(QString::fromStdString(s.payload_format)));
    if (s.has_thumbnail && library) {
      try {
        const std::string png = library->thumbnail(s.name, s.version);
        QImage image;
        if (image.loadFromData(reinterpret_cast<const uchar*>(png.data()),
                               static_cast<int>(png.size()), "PNG"))
          item->setIcon(QIcon(QPixmap::fromImage(image)));
      } catch (const std::exception&) {
      }
    }
  }
}

}  // namespace viscera::studio
