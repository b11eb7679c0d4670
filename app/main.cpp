// servodesk: the IDE's entry point. Opens the main window connected to a simulated BDS5 (or --port), or
// runs the screenshot tour and exits.
#include "command_line.h"
#include "main_window.h"
#include "screenshot_tour.h"

#include "resources/resources.h"

#include <QApplication>
#include <QIcon>

int main(int argc, char** argv) {
    QApplication application(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
    QCoreApplication::setApplicationName(QStringLiteral("ServoDesk"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SERVODESK_VERSION));
    resources::initialize();
    QApplication::setWindowIcon(QIcon(resources::kAppIcon));

    const auto options = app::parseCommandLine(QCoreApplication::arguments());
    if (!options) return 2;

    app::MainWindow window;
    if (options->screenshotTourDir.isEmpty()) {
        window.restoreLayout();
        window.connectDrive(options->connection);
        window.show();
        return QApplication::exec();
    }

    window.resize(app::ScreenshotTour::kWindowSize);
    window.connectDrive(options->connection);
    window.show();
    app::ScreenshotTour tour(window, options->screenshotTourDir);
    QObject::connect(&tour, &app::ScreenshotTour::finished, &application, &QCoreApplication::exit);
    tour.start();
    return QApplication::exec();
}
