#include "studio/ui/training_launcher.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include "core/error.h"

namespace viscera::studio {

QString summarize_report(const nlohmann::json& r) {
  if (!r.is_object()) return QObject::tr("No report was written.");
  QStringList lines;
  lines << QObject::tr("Simulated %1 s in %2 steps (%3 s wall clock).")
               .arg(r.value("simulated_time", 0.0), 0, 'f', 3)
               .arg(r.value("steps", 0))
               .arg(r.value("wall_time", 0.0), 0, 'f', 2);
  lines << QObject::tr("Ended: %1.").arg(QString::fromStdString(r.value("end_reason", "")));
  lines << QObject::tr("Largest displacement %1 mm.")
               .arg(1000.0 * r.value("max_displacement", 0.0), 0, 'f', 2);
  if (r.contains("tasks")) {
    for (const auto& task : r["tasks"]) {
      lines << QObject::tr("Task %1: %2.")
                   .arg(QString::fromStdString(task.value("name", task.value("id", ""))),
                        QString::fromStdString(task.value("status", "")));
    }
  }
  if (r.contains("score") && r["score"].is_number()) {
    lines << QObject::tr("Score %1.").arg(r["score"].get<double>(), 0, 'f', 1);
  } else if (r.contains("score")) {
    const std::string reason = r.value("score_reason", nlohmann::json()).is_string()
                                   ? r["score_reason"].get<std::string>()
                                   : std::string();
    lines << QObject::tr("No score: %1.").arg(QString::fromStdString(reason));
  }
  return lines.join('\n');
}

QStringList input_arguments(const TrainingInput& input) {
  switch (input.kind) {
    case TrainingInput::Kind::Gamepad:
      return {QStringLiteral("--input"), QStringLiteral("gamepad")};
    case TrainingInput::Kind::Device:
      return {QStringLiteral("--input"), QStringLiteral("udp:%1").arg(input.port)};
    case TrainingInput::Kind::Script:
      return {QStringLiteral("--script"), input.script};
    case TrainingInput::Kind::Keyboard:
      break;
  }
  return {QStringLiteral("--input"), QStringLiteral("keyboard")};
}

QString failure_sentence(const TrainingResult& result) {
  if (result.exit_code == 0 && !result.crashed) return {};
  if (result.crashed && result.exit_code != static_cast<int>(core::ExitCode::SimulationFailed))
    return QObject::tr("The simulator stopped before the session ended.");
  const QString prefix = QStringLiteral("viscera-sim: ");
  QString line;
  for (const QString& candidate : result.output.split('\n')) {
    if (candidate.startsWith(prefix)) line = candidate.mid(prefix.size()).trimmed();
  }
  if (line.isEmpty()) line = QObject::tr("it ended with code %1").arg(result.exit_code);
  if (result.exit_code == static_cast<int>(core::ExitCode::SimulationFailed))
    return QObject::tr("The simulation failed: %1").arg(line);
  return QObject::tr("The session could not run: %1").arg(line);
}

TrainingLauncher::TrainingLauncher(QObject* parent)
    : QObject(parent), simulator_(default_simulator()) {
  qRegisterMetaType<TrainingResult>("viscera::studio::TrainingResult");
}

TrainingLauncher::~TrainingLauncher() {
  if (process_ != nullptr) {
    process_->disconnect(this);
    process_->kill();
    process_->waitForFinished(5000);
  }
}

QString TrainingLauncher::default_simulator() {
  return QCoreApplication::applicationDirPath() + QStringLiteral("/viscera-sim");
}

QString TrainingLauncher::prepare() {
  if (running()) throw core::InputError("a training session is already running");
  folder_ = std::make_unique<QTemporaryDir>();
  if (!folder_->isValid()) {
    throw core::OutputError("cannot create a temporary folder for the session: " +
                            folder_->errorString().toStdString());
  }
  return folder_->filePath(QStringLiteral("session.vscene"));
}

bool TrainingLauncher::running() const {
  return process_ != nullptr;
}

void TrainingLauncher::start(double duration_s, const QString& script) {
  QStringList arguments = {QStringLiteral("--headless")};
  if (!script.isEmpty()) {
    if (!QFileInfo(script).isFile())
      throw core::InputError("the script does not exist", {script.toStdString(), "", ""});
    arguments << QStringLiteral("--script") << script;
  }
  launch(arguments, duration_s);
}

void TrainingLauncher::start_interactive(const TrainingInput& input, double duration_s) {
  if (input.kind == TrainingInput::Kind::Script && !QFileInfo(input.script).isFile())
    throw core::InputError("the script does not exist", {input.script.toStdString(), "", ""});
  launch(input_arguments(input), duration_s);
}

void TrainingLauncher::launch(QStringList arguments, double duration_s) {
  if (running()) throw core::InputError("a training session is already running");
  if (folder_ == nullptr) throw core::UsageError("prepare() the session package first");
  if (!QFileInfo(simulator_).isExecutable()) {
    throw core::InputError("the simulator is missing", {simulator_.toStdString(), "", ""});
  }
  arguments.prepend(folder_->filePath(QStringLiteral("session.vscene")));
  arguments.prepend(QStringLiteral("run"));
  arguments << QStringLiteral("--report") << folder_->filePath(QStringLiteral("report"));
  if (duration_s > 0.0) arguments << QStringLiteral("--duration") << QString::number(duration_s);
  process_ = new QProcess(this);
  process_->setProcessChannelMode(QProcess::MergedChannels);
  connect(process_, qOverload<int, QProcess::ExitStatus>(&QProcess::finished), this,
          &TrainingLauncher::on_finished);
  connect(process_, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
    if (error == QProcess::FailedToStart) on_finished(-1, QProcess::CrashExit);
  });
  process_->start(simulator_, arguments);
}

void TrainingLauncher::stop() {
  if (process_ != nullptr) process_->kill();
}

void TrainingLauncher::on_finished(int exit_code, QProcess::ExitStatus status) {
  if (process_ == nullptr) return;
  TrainingResult result;
  result.exit_code = exit_code;
  result.crashed = status == QProcess::CrashExit;
  result.output = QString::fromLocal8Bit(process_->readAll());
  process_->deleteLater();
  process_ = nullptr;
  const QString report = folder_->filePath(QStringLiteral("report/report.json"));
  QFile file(report);
  if (file.open(QIODevice::ReadOnly)) {
    const nlohmann::json parsed =
        nlohmann::json::parse(file.readAll().toStdString(), nullptr, false);
    if (!parsed.is_discarded()) {
      result.report = parsed;
      result.report_path = report;
    }
  }
  emit finished(result);
}

}  // namespace viscera::studio
