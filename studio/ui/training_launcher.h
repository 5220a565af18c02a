#pragma once
/// Launch training (issue 9 §8): the document is exported to a temporary package and
/// `viscera-sim run PKG --headless --report DIR` runs on it as a separate process, so a crash
/// of the session never takes the studio down; report.json is read when it ends.

#include <QObject>
#include <QProcess>
#include <QString>
#include <QTemporaryDir>
#include <memory>
#include <nlohmann/json.hpp>

namespace viscera::studio {

/// How a session ended.
struct TrainingResult {
  int exit_code = -1;
  bool crashed = false;
  QString report_path;    ///< DIR/report.json, empty when it was not written
  nlohmann::json report;  ///< the parsed report, or null
  QString output;         ///< the simulator's standard output and error
};

/// A few lines a clinician reads: time simulated, how it ended, displacement, tasks, score.
QString summarize_report(const nlohmann::json& report);

class TrainingLauncher : public QObject {
  Q_OBJECT

 public:
  explicit TrainingLauncher(QObject* parent = nullptr);
  ~TrainingLauncher() override;

  /// viscera-sim beside the running executable.
  static QString default_simulator();
  void set_simulator(const QString& path) { simulator_ = path; }
  const QString& simulator() const { return simulator_; }

  /// A fresh temporary folder for the next session; returns the package path to write there.
  /// Throws core::OutputError when no temporary folder can be made.
  QString prepare();
  /// Starts the simulator on the package prepare() named; `duration_s` > 0 limits the session.
  /// Throws core::InputError when the simulator is missing or a session is already running.
  void start(double duration_s);
  bool running() const;
  /// Stops a running session (finished() follows with crashed = true).
  void stop();

 signals:
  void finished(const viscera::studio::TrainingResult& result);

 private:
  void on_finished(int exit_code, QProcess::ExitStatus status);

  QString simulator_;
  std::unique_ptr<QTemporaryDir> folder_;
  QProcess* process_ = nullptr;
};

}  // namespace viscera::studio

Q_DECLARE_METATYPE(viscera::studio::TrainingResult)
