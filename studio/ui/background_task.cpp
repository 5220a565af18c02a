#include "studio/ui/background_task.h"

#include <QEventLoop>
#include <QPointer>
#include <QProgressDialog>
#include <QThread>
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

  QPointer<QProgressDialog> shown(&dialog);
  core::Progress progress([shown](double fraction, const std::string& stage) {
    const int value = static_cast<int>(std::lround(1000.0 * fraction));
    const QString label = QString::fromStdString(stage);
    QMetaObject::invokeMethod(
        shown.data(),
        [shown, value, label] {
          if (shown.isNull()) return;
          shown->setLabelText(label);
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
  return error;
}

}  // namespace viscera::studio
