#pragma once
/// The variants gallery (issue 9 §6): a dock listing the variants "Generate variants…" made, each
/// as a thumbnail with a validation badge — a green tick when the variant passed every check, a
/// red cross when it did not, the failing check and its reason in the tooltip. Double-clicking a
/// variant asks the main window to open it as a new document.

#include <QImage>
#include <QWidget>
#include <vector>

#include "studio/document/scenario_document.h"
#include "studio/document/variant_batch.h"

class QListWidget;
class QLabel;

namespace viscera::studio {

/// A thumbnail of every object surface of `scenario` together (textures::render_surface_thumbnail,
/// software, deterministic); a dark square when it has no surface. Safe on a worker thread.
QImage scenario_thumbnail(const core::Scenario& scenario, int size = 128);

/// `thumbnail` with the validation badge drawn into its top-right corner.
QImage badged_thumbnail(const QImage& thumbnail, bool valid);

/// One generated variant with its picture.
struct GalleryEntry {
  Variant variant;
  QImage thumbnail;
};

class VariantsGallery : public QWidget {
  Q_OBJECT

 public:
  explicit VariantsGallery(QWidget* parent = nullptr);

  /// Shows `entries` (replacing what was shown); `files` are the package files (texture maps)
  /// an opened variant carries; `description` says where they came from.
  void set_variants(std::vector<GalleryEntry> entries, PackageFiles files,
                    const QString& description);
  int count() const { return static_cast<int>(entries_.size()); }
  const Variant& variant(int row) const {
    return entries_.at(static_cast<std::size_t>(row)).variant;
  }
  const PackageFiles& files() const { return files_; }
  QListWidget* list() const { return list_; }
  /// The tooltip of a row: "passed every check …" or "failed <check>: <detail> …".
  QString tooltip(int row) const;

 signals:
  /// A variant was double-clicked.
  void open_requested(int row);

 private:
  std::vector<GalleryEntry> entries_;
  PackageFiles files_;
  QListWidget* list_ = nullptr;
  QLabel* header_ = nullptr;
};

}  // namespace viscera::studio
