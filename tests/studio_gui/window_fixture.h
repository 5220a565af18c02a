#pragma once
/// What the studio's window suites share: a scratch folder, the options that keep autosave out
/// of the way, the error dialog's messages, and one patient package to open.

#include <QStringList>
#include <QTemporaryDir>
#include <QtTest/QtTest>
#include <cstdlib>
#include <filesystem>

#include "studio/ui/main_window.h"

namespace viscera::studio_tests {

class WindowFixture {
 protected:
  QTemporaryDir tmp_;
  std::filesystem::path patient_;  ///< the package open_patient() opens
  std::filesystem::path out_dir_;  ///< where images for a human to look at go
  QStringList errors_;             ///< what the error dialog would have shown

  std::filesystem::path dir() const { return std::filesystem::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options() const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / "recovery";
    o.autosave_interval_ms = 600'000;
    return o;
  }

  /// Checks the scratch folder and makes out_dir_ ($VISCERA_TEST_TMP, else the scratch folder).
  void make_folders() {
    QVERIFY(tmp_.isValid());
    const char* out = std::getenv("VISCERA_TEST_TMP");
    out_dir_ = out != nullptr ? std::filesystem::path(out) : dir();
    std::filesystem::create_directories(out_dir_);
  }

  /// A shown window with patient_ open, its errors collected in errors_.
  void open_patient(studio::MainWindow& window) {
    errors_.clear();
    window.set_error_handler([this](const QString& m) { errors_ << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.open_package(patient_));
  }
};

}  // namespace viscera::studio_tests
