#pragma once
/// Launch training (issue 9 §8, issue 16 item 5): the document is exported to a temporary
/// package and `viscera-sim run PKG … --report DIR` runs on it as a separate process, so a crash
/// of the session never takes the studio down; report.json is read when it ends. Interactive:
/// the endoscopic view opens in the simulator's window, driven by the input chosen (keyboard and
/// mouse, gamepad, a haptic device over UDP, or a script). Headless: the session runs without
/// a window, with a script or without an instrument.

#include <QObject>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <memory>
#include <nlohmann/json.hpp>

namespace viscera::studio {

/// What drives the instrument of an interactive session.
struct TrainingInput {
  enum class Kind { Keyboard, Gamepad, Device, Script };
  Kind kind = Kind::Keyboard;
  int port = 0;    ///< Device: UDP port on 127.0.0.1 the device sends its poses to (0: any)
  QString script;  ///< Script: a viscera-script file
};

/// The `viscera-sim run` arguments after the package for `input`: "--input keyboard",
/// "--input gamepad", "--input udp:PORT" or "--script FILE".
QStringList input_arguments(const TrainingInput& input);

/// How a session ended.
struct TrainingResult {
  int exit_code = -1;
  bool crashed = false;
  QString report_path;    ///< DIR/report.json, empty when it was not written
  nlohmann::json report;  ///< the parsed report, or null
  QString output;         ///< the simulator's standard output and error
};

/// One sentence for the studio from a failed session's output: the simulator's own error line
/// ("viscera-sim: …") without its prefix, prefixed by what failed ("The simulation failed: "
/// for a core::SimulationError, exit code 5); empty when the session succeeded.
QString failure_sentence(const TrainingResult& result);

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
  /// Starts the simulator headless on the package prepare() named; `duration_s` > 0 limits the
  /// session; a `script` drives its instrument (empty: no instrument). Throws core::InputError
  /// when the simulator is missing or a session is already running.
  void start(double duration_s, const QString& script = {});
  /// Starts the interactive session: the simulator's endoscopic view in its own window, driven
  /// by `input`. Same errors as start(); a script input needs an existing file.
  void start_interactive(const TrainingInput& input, double duration_s);
  bool running() const;
  /// Stops a running session (finished() follows with crashed = true).
  void stop();

 signals:
  void finished(const viscera::studio::TrainingResult& result);

 private:
  void on_finished(int exit_code, QProcess::ExitStatus status);
  void launch(QStringList arguments, double duration_s);

  QString simulator_;
  std::unique_ptr<QTemporaryDir> folder_;
  QProcess* process_ = nullptr;
};

}  // namespace viscera::studio

Q_DECLARE_METATYPE(viscera::studio::TrainingResult)
