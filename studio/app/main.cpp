/// `viscera-studio`: the Qt + VTK authoring window (issue 9). Usage: viscera-studio [PACKAGE]

#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>

#include "core/version.h"
#include "studio/ui/main_window.h"

int main(int argc, char** argv) {
  // VTK renders through this format; it must be the default before QApplication exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Viscera"));
  QApplication::setApplicationName(QStringLiteral("viscera-studio"));
  QApplication::setApplicationVersion(QString::fromStdString(viscera::core::viscera_version()));

  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral("Viscera scenario authoring studio"));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(QStringLiteral("package"),
                               QStringLiteral("Scenario package to open (.vscene or .vscz)"));
  const QCommandLineOption library(
      QStringLiteral("library"),
      QStringLiteral("Asset library database (default: $VISCERA_LIBRARY, else XDG data folder)"),
      QStringLiteral("path"));
  parser.addOption(library);
  parser.process(app);

  viscera::studio::MainWindowOptions options;
  options.library = parser.value(library).toStdString();
  viscera::studio::MainWindow window(options);
  window.show();
  const bool recovered = window.offer_recovery();
  if (!recovered && !parser.positionalArguments().isEmpty()) {
    window.open_package(parser.positionalArguments().first().toStdString());
  }
  return QApplication::exec();
}
