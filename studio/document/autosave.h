#pragma once
/// Autosave and crash recovery (issue 9 §1). While a document has unsaved changes, a copy is
/// written every interval (a minute by default) to <recovery dir>/recovery.vscene, with
/// recovery.json naming the document's own path and the time. Saving or closing cleanly removes
/// the copy, so a copy found at start-up means the last session ended without saving — a crash —
/// and the studio offers to recover it. The write runs on a worker thread on a snapshot.

#include <QDateTime>
#include <QObject>
#include <QTimer>
#include <filesystem>
#include <memory>
#include <optional>

#include "studio/document/scenario_document.h"

namespace viscera::studio {

/// A recovery copy left by an earlier session.
struct RecoveryCopy {
  std::filesystem::path package;        ///< the autosaved package
  std::filesystem::path original_path;  ///< where the document was saved, or empty
  QDateTime written;                    ///< UTC
};

class Autosave : public QObject {
  Q_OBJECT

 public:
  /// Watches `document`; writes into `recovery_dir` (created when needed) every `interval_ms`.
  Autosave(ScenarioDocument& document, std::filesystem::path recovery_dir, int interval_ms = 60'000,
           QObject* parent = nullptr);
  ~Autosave() override;

  /// The default folder: <AppLocalDataLocation>/recovery.
  static std::filesystem::path default_recovery_dir();
  /// The copy an earlier session left in `recovery_dir`, if any (a broken copy counts as none).
  static std::optional<RecoveryCopy> find_recovery(const std::filesystem::path& recovery_dir);

  int interval_ms() const { return timer_.interval(); }
  const std::filesystem::path& recovery_dir() const { return dir_; }
  /// Writes a copy now if the document is dirty and no write is running; returns whether it
  /// started one. autosaved() or autosave_failed() follows.
  bool save_now();
  /// Removes the recovery copy (after a save, a clean close, or a declined recovery).
  void discard();
  /// Waits for a running write to end (used before quitting).
  void wait();

 signals:
  void autosaved(const QString& package);
  void autosave_failed(const QString& message);

 private:
  void finish_write();

  ScenarioDocument& document_;
  std::filesystem::path dir_;
  QTimer timer_;
  class QThread* worker_ = nullptr;
  std::shared_ptr<QString> pending_error_;  ///< set by the running write
};

}  // namespace viscera::studio
