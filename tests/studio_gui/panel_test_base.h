#pragma once
// What the organ-panel QtTests share: a ball package, window options without autosave noise,
// and a shown main window with the ball open and selected.

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>

#include "core/package/scenario_package.h"
#include "studio/ui/main_window.h"
#include "templates/template_catalog.h"

namespace viscera::studio_tests {

class PanelTestBase : public QObject {
 protected:
  QTemporaryDir tmp_;
  std::filesystem::path ball_package_;

  std::filesystem::path dir() const { return std::filesystem::path(tmp_.path().toStdString()); }

  studio::MainWindowOptions options() const {
    studio::MainWindowOptions o;
    o.recovery_dir = dir() / "recovery";
    o.autosave_interval_ms = 600'000;
    return o;
  }

  /// Writes the ball template (12 mm cells) as ball.vscene in the temporary folder.
  void make_ball_package() {
    QVERIFY(tmp_.isValid());
    const core::Scenario scenario =
        templates::build_from_template("ball", {{"cell_size", "0.012"}}, 1);
    ball_package_ = dir() / "ball.vscene";
    core::write_package(scenario, ball_package_);
  }

  /// A shown window with the ball open and selected; errors land in `errors`.
  void open_ball(studio::MainWindow& window, QStringList& errors) {
    window.set_error_handler([&errors](const QString& m) { errors << m; });
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.open_package(ball_package_));
    window.select_object("ball");
    QVERIFY(window.document().scenario().find_object("ball") != nullptr);
  }
};

}  // namespace viscera::studio_tests
