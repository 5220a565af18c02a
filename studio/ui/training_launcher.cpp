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
  }
  return lines.join('\n');
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

void TrainingLauncher::start(double duration_s) {
  if (running()) throw core::InputError("a training session is already running");
  if (folder_ == nullptr) throw core::UsageError("prepare() the session package first");
  if (!QFileInfo(simulator_).isExecutable()) {
    throw core::InputError("the simulator is missing", {simulator_.toStdString(), "", ""});
  }
  QStringList arguments = {QStringLiteral("run"),
                           folder_->filePath(QStringLiteral("session.vscene")),
                           QStringLiteral("--headless"), QStringLiteral("--report"),
                           folder_->filePath(QStringLiteral("report"))};
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
