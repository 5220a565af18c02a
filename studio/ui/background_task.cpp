#include "studio/ui/background_task.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QPointer>
#include <QProgressDialog>
#include <QThread>
#include <QTimer>
#include <cmath>

#include "studio/ui/input_blocker.h"

namespace viscera::studio {

std::exception_ptr run_in_background(QWidget* parent, const QString& title,
                                     const std::function<void(core::Progress&)>& work,
                                     int show_after_ms) {
  QProgressDialog dialog(title, QObject::tr("Cancel"), 0, 1000, parent);
  dialog.setWindowTitle(title);
  dialog.setWindowModality(Qt::WindowModal);
  dialog.setMinimumDuration(show_after_ms);
  dialog.setAutoClose(false);
  dialog.setAutoReset(false);
  dialog.setValue(0);

  // The label shows the stage and the time since the work started, updated twice a second,
  // so a long step that reports no fraction (one Mesh_3 refinement) still shows it is alive.
  QElapsedTimer elapsed;
  elapsed.start();
  QString stage_text = title;
  const auto show_label = [&dialog, &elapsed, &stage_text] {
    const qint64 seconds = elapsed.elapsed() / 1000;
    dialog.setLabelText(seconds < 2 ? stage_text
                                    : QObject::tr("%1 — %2 s").arg(stage_text).arg(seconds));
  };
  QTimer clock;
  QObject::connect(&clock, &QTimer::timeout, &dialog, show_label);
  clock.start(500);

  QPointer<QProgressDialog> shown(&dialog);
  core::Progress progress(
      [shown, &stage_text, show_label](double fraction, const std::string& stage) {
        const int value = static_cast<int>(std::lround(1000.0 * fraction));
        const QString label = QString::fromStdString(stage);
        QMetaObject::invokeMethod(
            shown.data(),
            [shown, value, label, &stage_text, show_label] {
              if (shown.isNull()) return;
              stage_text = label;
              show_label();
              shown->setValue(value);
            },
            Qt::QueuedConnection);
      });
  QObject::connect(&dialog, &QProgressDialog::canceled, &dialog,
                   [&progress] { progress.cancel(); });
  // The work reads the document: no edit (Undo included) may reach it until the work ends,
  // also before the dialog shows.
  const InputBlocker blocker(&dialog);

  std::exception_ptr error;
  QThread* thread = QThread::create([&] {
    try {
      work(progress);
    } catch (...) {
      error = std::current_exception();
    }
  });
  QEventLoop loop;
  QObject::connect(thread, &QThread::finished, &loop, &QEventLoop::quit);
  thread->start();
  loop.exec();
  thread->wait();
  delete thread;
  clock.stop();
  return error;
}

}  // namespace viscera::studio
