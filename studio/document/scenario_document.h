#pragma once
/// The studio's document (issue 9 §1): one scenario, the package files that travel with it
/// (baked texture maps), where it is saved, and its undo stack. Widgets never edit the scenario
/// directly: every change is a QUndoCommand (document_commands.h) that calls the mutators below,
/// so undo and redo cover everything and the dirty state is the stack's clean state.
/// Opening and saving go through the same library calls as the CLI (core::read_package,
/// core::write_package, exporters::read_package_textures).

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <filesystem>
#include <map>
#include <string>

#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::studio {

/// Package files other than the manifest and meshes: package path → bytes (baked texture maps,
/// model objects' models).
using PackageFiles = std::map<std::string, std::string>;

/// A scenario with its package files, as read from or written to disk.
struct DocumentContent {
  core::Scenario scenario;
  PackageFiles files;
};

/// Reads a package folder or .vscz with its texture maps and model files. Throws core::Error
/// subclasses naming the file; safe to call from a worker thread.
DocumentContent read_document_content(const std::filesystem::path& path,
                                      core::Progress& progress = core::Progress::none());
/// Writes a package (folder, or zipped for .vscz) atomically. Throws core::Error subclasses;
/// safe to call from a worker thread on a copy of the content.
void write_document_content(const DocumentContent& content, const std::filesystem::path& path,
                            core::Progress& progress = core::Progress::none());

/// What a change touched, so views can refresh only what they show.
/// View: only the view state (view_state.h) changed — visibility and opacity.
enum class ChangeKind { Everything, Objects, Materials, View };

class ScenarioDocument : public QObject {
  Q_OBJECT

 public:
  explicit ScenarioDocument(QObject* parent = nullptr);
  /// Silent: QUndoStack's destructor clears the stack, which must not look like a save.
  ~ScenarioDocument() override;

  const core::Scenario& scenario() const { return content_.scenario; }
  const PackageFiles& files() const { return content_.files; }
  const DocumentContent& content() const { return content_; }
  QUndoStack* undo_stack() { return &undo_stack_; }

  /// Where the document was last opened from or saved to; empty for a new document.
  const std::filesystem::path& path() const { return path_; }
  /// Unsaved changes: edits since the last save, or a new/recovered document never saved.
  bool is_dirty() const { return unsaved_ || !undo_stack_.isClean(); }
  /// File name shown in the title ("untitled" for a new document).
  QString display_name() const;

  /// Replaces the content with a new, never-saved document (e.g. built from a template); clears
  /// undo history. `path` may name where it came from (a recovered document's original).
  void reset(DocumentContent content, const std::filesystem::path& path = {}, bool unsaved = true);
  /// Reads `path` and replaces the content on success; on error throws and keeps the document.
  void open(const std::filesystem::path& path, core::Progress& progress = core::Progress::none());
  /// Adopts content that a worker read from `path`; clears undo history, marks clean.
  void adopt_opened(DocumentContent content, const std::filesystem::path& path);
  /// Writes to path() (which must be set) / to `path`; on error throws and stays dirty.
  void save(core::Progress& progress = core::Progress::none());
  void save_as(const std::filesystem::path& path,
               core::Progress& progress = core::Progress::none());
  /// Records that the current state was written to `path` (by a worker writing a copy).
  void mark_saved(const std::filesystem::path& path);

  // Mutators for QUndoCommands only: each emits changed().
  core::Scenario& edit_scenario() { return content_.scenario; }
  PackageFiles& edit_files() { return content_.files; }
  void notify_changed(ChangeKind kind, const QString& id = {});

 signals:
  /// The scenario changed; `id` names the object or material when only one changed.
  void changed(viscera::studio::ChangeKind kind, const QString& id);
  /// The dirty state or the path changed (title bar).
  void status_changed();

 private:
  DocumentContent content_;
  std::filesystem::path path_;
  bool unsaved_ = false;
  QUndoStack undo_stack_;
};

}  // namespace viscera::studio

Q_DECLARE_METATYPE(viscera::studio::ChangeKind)
