#pragma once
/// The studio's main window (issue 9): a 3D view of the document's scenario in the centre, the
/// scene tree and the material panel docked on the left and right, a training report dock, and
/// the File, Edit, Create and Training menus. It owns the document and its autosave. Every
/// action is also a public function so tests drive the real window; errors go to a dialog with
/// a one-line message and leave the document as it was. Long work runs off the UI thread.

#include <QByteArray>
#include <QMainWindow>
#include <QStringList>
#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include "core/image/image_volume.h"
#include "studio/document/autosave.h"
#include "studio/document/primitive_objects.h"
#include "studio/document/scenario_document.h"
#include "studio/document/variant_batch.h"
#include "studio/document/view_state.h"
#include "studio/ui/training_launcher.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QMenu;
class QPlainTextEdit;

namespace viscera::studio {

class MaterialPanel;
class OrganPanels;
class SceneTree;
class SegmentationPanel;
class LabelOverlay;
class VolumeRendering;
class SliceViews;
class SceneView;
class VariantsGallery;
class LibraryBrowser;
class DisplayPanel;

/// Where the window keeps its recovery copy and how often it writes it.
struct MainWindowOptions {
  std::filesystem::path recovery_dir = Autosave::default_recovery_dir();
  int autosave_interval_ms = 60'000;
  QString simulator = TrainingLauncher::default_simulator();
  /// The asset library database; empty: VISCERA_LIBRARY, else XDG (core::resolve_library_path).
  std::string library;
};

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(MainWindowOptions options = {}, QWidget* parent = nullptr);
  ~MainWindow() override;

  ScenarioDocument& document() { return document_; }
  SceneView* scene_view() const { return view_; }
  SceneTree* scene_tree() const { return tree_; }
  MaterialPanel* material_panel() const { return materials_; }
  SliceViews* slice_views() const { return slices_; }
  SegmentationPanel* segmentation_panel() const { return segmentation_; }
  LabelOverlay* label_overlay() const { return overlay_; }
  VolumeRendering& volume_rendering() { return *volume_rendering_; }
  /// Texture, vessel and pathology panels (organ_panels.h).
  OrganPanels* organ_panels() const { return organ_panels_; }
  Autosave& autosave() { return *autosave_; }
  TrainingLauncher& launcher() { return launcher_; }

  /// Each returns false after showing an error dialog (the document unchanged).
  bool open_package(const std::filesystem::path& path);
  bool save();
  bool save_as(const std::filesystem::path& path);
  /// A new, unsaved document from a catalogue template with parameter `overrides` (text values
  /// as for `viscera new --set`) and `seed`, built off the UI thread.
  bool new_from_template(const std::string& name,
                         const std::map<std::string, std::string>& overrides = {},
                         std::uint64_t seed = 1);
  /// Reads an image volume (a DICOM folder or a DICOM, NIfTI, MetaImage, NRRD, VTI, INR or
  /// MINC file, through importers::read_volume) off the UI thread and shows it in the three slice
  /// views and as planes in the 3D view — a modelling aid, not part of the scenario.
  bool open_image_volume(const std::filesystem::path& path);
  /// Replaces the shown image volume by its block average over `factors` voxels
  /// (core::downsample), a coarser working copy for segmentation; labels start over.
  bool downsample_image_volume(const std::array<int, 3>& factors);
  /// Shows or hides the volume rendering of the image volume in the 3D view
  /// (main_window_volume.cpp).
  void set_volume_rendering(bool shown);
  bool volume_rendering_shown() const;
  /// Applies a transfer-function preset ("CT soft tissue", "CT bone", "MR default") and shows
  /// the volume rendering; false (with an error) for an unknown name or without a volume.
  bool set_volume_preset(const QString& name);
  /// Builds the primitive off the UI thread, adds it as one undoable command and selects it.
  bool create_primitive(const PrimitiveRequest& request);
  /// Selects an object in the tree, the 3D view and the material panel.
  void select_object(const QString& id);

  // Seeing inside and one visibility model (issue 23 §2, §4; main_window_view.cpp).
  DisplayPanel* display_panel() const { return display_; }
  /// Shows or hides objects and vessel trees (visibility keys, view_state.h) as one undoable
  /// view-state command; SceneTree::kImageVolumeKey shows or hides the image volume's slice
  /// planes (not part of the document). False after an error.
  bool set_visible(const QStringList& keys, bool visible);
  /// Object `id`'s opacity in [0.05, 1], undoable (a slider drag is one step).
  bool set_object_opacity(const QString& id, double opacity);
  /// File ▸ Close: after offering to save, an empty untitled document and no image volume.
  /// False when the user cancels.
  bool close_document();
  /// Removes the image volume: slice views, planes, volume rendering and segmentation.
  void close_image_volume();
  bool has_image_volume() const;
  /// Shows or hides the image volume's three slice planes in the 3D view.
  void set_slice_planes_shown(bool shown);
  bool slice_planes_shown() const;
  /// Exports to a temporary package and starts the headless simulator, its instrument driven by
  /// `script` (empty: none); its report appears in the report dock when it ends
  /// (training_finished()).
  bool launch_training(double duration_s = 0.0, const QString& script = {});
  /// Training ▸ Launch: exports to a temporary package and opens the simulator's interactive
  /// endoscopic view on it, driven by `input`; the report appears in the report dock when the
  /// session ends, a failure as one sentence in the error dialog.
  bool launch_interactive_training(const TrainingInput& input, double duration_s = 0.0);
  QString report_text() const;

  /// Generates `request.count` variants of the document off the UI thread (progress, Cancel;
  /// variant_batch.h) and shows them in the variants gallery dock.
  bool generate_variants(const VariantRequest& request);
  /// Opens gallery row `row` as a new, unsaved document after offering to save a dirty one.
  bool open_variant(int row);
  VariantsGallery* variants_gallery() const { return variants_; }

  /// Adds the selected object (as a one-object package) / its material to the asset library
  /// under `name` (empty: the object's / material's id) and lists it in the library browser.
  bool add_selected_object_to_library(const std::string& name = {});
  bool add_selected_material_to_library(const std::string& name = {});
  /// A library entry dropped (kAssetMimeType) on object `target` ("" for none) of the 3D view or
  /// scene tree: a model is added to the scene as one undoable command, a material assigned to
  /// the target. Returns whether the drop changed the document (errors go to the dialog).
  bool drop_asset(const class QMimeData* mime, const QString& target);
  LibraryBrowser* library_browser() const { return library_; }

  /// If an earlier session left a recovery copy, asks (through `ask`, a dialog by default)
  /// whether to recover it and opens it as an unsaved document; returns whether it did.
  bool offer_recovery(std::function<bool(const RecoveryCopy&)> ask = {});
  /// Replaces the error dialog (tests): receives the one-line message.
  void set_error_handler(std::function<void(const QString&)> handler) {
    error_handler_ = std::move(handler);
  }
  QStringList recent_files() const;

 signals:
  void training_finished(const viscera::studio::TrainingResult& result);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void build_menus();
  void build_docks();
  void build_asset_docks();  // main_window_assets.cpp: variants gallery, asset library
  void update_title();
  void on_document_changed(ChangeKind kind, const QString& id);
  void show_error(const QString& message);
  /// Runs `work` in the background; shows its error (not a cancellation) and returns false.
  bool run(const QString& title, const std::function<void(core::Progress&)>& work);
  void remember_recent(const std::filesystem::path& path);
  void rebuild_recent_menu();
  void ask_create(PrimitiveKind kind);
  void show_image_volume(const core::ImageVolume& volume);
  void build_volume_views();
  void build_volume_menu(QMenu* view);
  void build_view_docks();  // main_window_view.cpp: the display dock
  void build_view_menu_items(QMenu* file, QMenu* view);
  /// Restores the window geometry and dock layout of the last session (QSettings), else sizes
  /// the window to most of the screen with the 3D view the largest pane.
  void restore_layout();
  /// The document's view state (studio/view.json); nothing after showing the error of a
  /// damaged one.
  std::optional<ViewState> read_view_state();
  void save_layout() const;
  bool ask_save_as();
  /// Exports the document for the next training session; false after showing the error.
  bool export_session_package();
  void show_training_result(const TrainingResult& result);
  bool maybe_save();

  MainWindowOptions options_;
  ScenarioDocument document_;
  Autosave* autosave_ = nullptr;
  TrainingLauncher launcher_;
  SceneView* view_ = nullptr;
  SceneTree* tree_ = nullptr;
  MaterialPanel* materials_ = nullptr;
  QPlainTextEdit* report_ = nullptr;
  SliceViews* slices_ = nullptr;
  OrganPanels* organ_panels_ = nullptr;
  class QDockWidget* slice_dock_ = nullptr;
  SegmentationPanel* segmentation_ = nullptr;
  LabelOverlay* overlay_ = nullptr;
  std::unique_ptr<VolumeRendering> volume_rendering_;
  class QActionGroup* preset_actions_ = nullptr;
  class QAction* volume_action_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  VariantsGallery* variants_ = nullptr;
  class QDockWidget* variants_dock_ = nullptr;
  LibraryBrowser* library_ = nullptr;
  DisplayPanel* display_ = nullptr;
  std::array<QDockWidget*, 2> first_layout_docks_{nullptr,
                                                  nullptr};  ///< left, right: sized on show
  /// The last session's dock layout, applied again on the first show: restoreState before the
  /// window has its final size lets the layout squeeze the docks to fit the default size.
  QByteArray restored_state_;
  class QAction* slice_planes_action_ = nullptr;
  std::function<void(const QString&)> error_handler_;
};

}  // namespace viscera::studio
