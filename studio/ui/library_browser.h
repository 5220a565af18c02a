#pragma once
/// The asset library browser (issue 9 §7; seed 001 §3.3): a dock over the SQLite asset library
/// (core/library/asset_library.h) at the path `viscera library` uses (--library,
/// VISCERA_LIBRARY, XDG; resolve_library_path). It lists the newest version of each entry with
/// its thumbnail, filtered by type and by a search text (name or tag), and drags entries out as
/// QMimeData of kAssetMimeType; the main window's drop handler (asset_drop.h) adds a model to
/// the scene or assigns a material. Its buttons ask the main window to add the selected object
/// or its material to the library.

#include <QWidget>
#include <filesystem>
#include <optional>

#include "core/library/asset_library.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QMimeData;

namespace viscera::studio {

/// The mime type of a dragged library entry: JSON {"library", "name", "version", "type"}.
inline constexpr const char* kAssetMimeType = "application/x-viscera-asset";

/// A library entry named in a drag.
struct AssetReference {
  std::filesystem::path library;
  std::string name;
  int version = 0;
  core::AssetType type = core::AssetType::Model;
};

/// The mime data of `summary` in `library` (caller owns it).
QMimeData* asset_mime_data(const std::filesystem::path& library, const core::AssetSummary& summary);
/// The entry a mime data names; nullopt when it holds no (well-formed) asset.
std::optional<AssetReference> asset_from_mime(const QMimeData* mime);

class LibraryBrowser : public QWidget {
  Q_OBJECT

 public:
  /// Opens (creating if needed) the library at `path` when it is first listed.
  explicit LibraryBrowser(std::filesystem::path path, QWidget* parent = nullptr);

  const std::filesystem::path& library_path() const { return path_; }
  /// Reads the listing again; shows an error line instead when the library cannot be opened.
  void refresh();
  /// nullopt: every type.
  void set_type_filter(std::optional<core::AssetType> type);
  void set_search(const QString& text);
  /// The names shown, in order.
  QStringList shown_names() const;
  QListWidget* list() const { return list_; }
  /// The summary of the entry in `row` of the list.
  const core::AssetSummary& summary(int row) const;

 signals:
  void add_object_requested();
  void add_material_requested();

 private:
  void show_entries();

  std::filesystem::path path_;
  std::vector<core::AssetSummary> entries_;  // all newest versions, then filtered
  std::vector<core::AssetSummary> shown_;
  QComboBox* type_ = nullptr;
  QLineEdit* search_ = nullptr;
  QListWidget* list_ = nullptr;
  QLabel* status_ = nullptr;
};

}  // namespace viscera::studio
