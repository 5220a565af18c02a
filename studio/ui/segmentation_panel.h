#pragma once
/// The segmentation dock (issue 9 §4; seed 001 §3.3): builds a label map on the opened image
/// volume with thresholds, region growing from a seed clicked in a slice view, morphological
/// opening/closing and keep-largest — the functions of `viscera segment` — and meshes one label
/// into an organ object (closed surface, tets, embedding, default material; the pipeline of
/// `viscera mesh tets`) off the UI thread with progress and Cancel, added to the document as
/// one undoable command. Every button is also a public function; each returns false after
/// reporting its error, leaving labels and document as they were.

#include <QUndoStack>
#include <QWidget>
#include <functional>
#include <optional>

#include "core/progress.h"
#include "studio/document/scenario_document.h"
#include "studio/document/segmentation.h"

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace viscera::studio {

class SegmentationPanel : public QWidget {
  Q_OBJECT

 public:
  SegmentationPanel(ScenarioDocument& document, QWidget* parent = nullptr);

  /// Starts a new, empty segmentation on `volume`.
  void set_volume(const core::ImageVolume& volume);
  const Segmentation& segmentation() const { return segmentation_; }
  /// Receives one-line error messages (the main window's error dialog).
  void set_error_handler(std::function<void(const QString&)> handler) {
    error_handler_ = std::move(handler);
  }

  /// Voxels with lower ≤ value ≤ upper (volume units, e.g. HU) get `label`.
  bool segment_threshold(double lower, double upper, int label);
  /// The seed for region growing, world point in m (a click in a slice view sets it).
  void set_seed(const core::Vec3& point);
  std::optional<core::Vec3> seed() const { return seed_; }
  /// Grows `label` from world point `point` (m) through voxels within `tolerance` of its value.
  bool grow_region_at(const core::Vec3& point, double tolerance, int label);
  /// Grows from the seed with the panel's tolerance and label.
  bool grow_from_seed();
  bool open_labels(int radius);
  bool close_labels(int radius);
  bool keep_largest();
  /// Replaces the labels by a label map file (.vti, or any volume read as labels) on the same
  /// grid as the volume.
  bool load_label_map(const std::filesystem::path& path);

  /// Meshes `request.label` into a new organ object off the UI thread and adds it to the
  /// document (one undo step); returns its id, or an empty string after an error or Cancel.
  QString mesh_segmentation(const OrganMeshRequest& request);
  /// The request from the panel's fields. Its label is the one last thresholded or grown
  /// (the user may change it).
  OrganMeshRequest mesh_request() const;

  /// The segmentation steps (issue 23 §5): each successful edit of the labels is one step;
  /// undo restores the label map before it byte for byte. Cleared with a new volume.
  QUndoStack* history() { return &history_; }
  bool undo_step();
  bool redo_step();

 signals:
  /// The label map changed (overlays redraw).
  void labels_changed();
  /// An organ object was added to the document.
  void organ_added(const QString& id);

 private:
  bool run(const QString& title, const std::function<void(core::Progress&)>& work);
  /// Runs a change of the labels in the background; on success updates status and overlay.
  bool edit(const QString& title, const std::function<void()>& change);
  void report(const QString& message);
  void update_status();

  ScenarioDocument& document_;
  Segmentation segmentation_;
  QUndoStack history_;
  std::optional<core::Vec3> seed_;
  std::function<void(const QString&)> error_handler_;
  QLabel* status_ = nullptr;
  QLabel* seed_label_ = nullptr;
  QDoubleSpinBox* lower_ = nullptr;
  QDoubleSpinBox* upper_ = nullptr;
  QSpinBox* threshold_label_ = nullptr;
  QDoubleSpinBox* tolerance_ = nullptr;
  QSpinBox* grow_label_ = nullptr;
  QSpinBox* radius_ = nullptr;
  QSpinBox* mesh_label_ = nullptr;
  QDoubleSpinBox* cell_size_mm_ = nullptr;
  QSpinBox* target_tets_ = nullptr;
  QSpinBox* triangles_ = nullptr;
  QLineEdit* name_ = nullptr;
};

}  // namespace viscera::studio
