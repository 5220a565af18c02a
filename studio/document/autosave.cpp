#include "studio/document/autosave.h"

#include <QStandardPaths>
#include <QThread>
#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "core/error.h"

namespace viscera::studio {
namespace {

constexpr const char* kPackageName = "recovery.vscene";
constexpr const char* kInfoName = "recovery.json";

}  // namespace

Autosave::Autosave(ScenarioDocument& document, std::filesystem::path recovery_dir, int interval_ms,
                   QObject* parent)
    : QObject(parent), document_(document), dir_(std::move(recovery_dir)) {
  timer_.setInterval(interval_ms);
  connect(&timer_, &QTimer::timeout, this, [this] { save_now(); });
  connect(&document_, &ScenarioDocument::status_changed, this, [this] {
    if (!document_.is_dirty()) discard();
  });
  timer_.start();
}

Autosave::~Autosave() {
  wait();
}

std::filesystem::path Autosave::default_recovery_dir() {
  const QString base = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation);
  return std::filesystem::path(base.toStdString()) / "recovery";
}

std::optional<RecoveryCopy> Autosave::find_recovery(const std::filesystem::path& recovery_dir) {
  const auto package = recovery_dir / kPackageName;
  const auto info = recovery_dir / kInfoName;
  std::error_code ec;
  if (!std::filesystem::is_directory(package, ec) || !std::filesystem::is_regular_file(info, ec)) {
    return std::nullopt;
  }
  std::ifstream in(info);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  RecoveryCopy copy;
  copy.package = package;
  copy.original_path = j.value("original_path", std::string());
  copy.written =
      QDateTime::fromString(QString::fromStdString(j.value("written", std::string())), Qt::ISODate);
  return copy;
}

bool Autosave::save_now() {
  if (worker_ != nullptr || !document_.is_dirty()) return false;
  auto content = std::make_shared<DocumentContent>(document_.content());
  auto error = std::make_shared<QString>();
  pending_error_ = error;
  const std::filesystem::path dir = dir_;
  const std::string original = document_.path().string();
  const QString written = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
  worker_ = QThread::create([content, error, dir, original, written] {
    try {
      std::filesystem::create_directories(dir);
      // The info file goes last and first away: a copy without it is never offered.
      std::filesystem::remove(dir / kInfoName);
      write_document_content(*content, dir / kPackageName);
      const nlohmann::json info = {{"original_path", original}, {"written", written.toStdString()}};
      const auto staged = dir / (std::string(kInfoName) + ".tmp");
      {
        std::ofstream out(staged);
        out << info.dump(2) << "\n";
        if (!out)
          throw core::OutputError("cannot write the recovery note", {staged.string(), "", ""});
      }
      std::filesystem::rename(staged, dir / kInfoName);
    } catch (const std::exception& e) {
      *error = QString::fromStdString(e.what());
    }
  });
  connect(worker_, &QThread::finished, this, [this] { finish_write(); });
  worker_->start();
  return true;
}

void Autosave::finish_write() {
  if (worker_ == nullptr) return;  // already settled by wait()
  worker_->deleteLater();
  worker_ = nullptr;
  const QString error = *pending_error_;
  if (!error.isEmpty()) {
    emit autosave_failed(error);
    return;
  }
  // A save that landed while the copy was written makes the copy stale.
  if (!document_.is_dirty()) {
    discard();
    return;
  }
  emit autosaved(QString::fromStdString((dir_ / kPackageName).string()));
}

void Autosave::discard() {
  if (worker_ != nullptr) return;  // finish_write() discards when the document is clean
  std::error_code ec;
  std::filesystem::remove(dir_ / kInfoName, ec);
  std::filesystem::remove_all(dir_ / kPackageName, ec);
}

void Autosave::wait() {
  if (worker_ == nullptr) return;
  worker_->wait();
  finish_write();  // settle now; the queued finished() then finds nothing to do
}

}  // namespace viscera::studio
