// servodesk: the IDE's entry point. Opens the main window connected to a simulated BDS5 (or --drive's family,
// or --port) with that family's sample program, or runs the screenshot tour and exits.
#include "command_line.h"
#include "editing/document_controller.h"
#include "editing/editor_area.h"
#include "main_window.h"
#include "screenshot_tour.h"

#include "resources/resources.h"

#include <QApplication>
#include <QIcon>
#include <QTemporaryDir>

int main(int argc, char** argv) {
    QApplication application(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
    QCoreApplication::setApplicationName(QStringLiteral("ServoDesk"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SERVODESK_VERSION));
    resources::initialize();
    QApplication::setWindowIcon(QIcon(resources::kAppIcon));

    const auto options = app::parseCommandLine(QCoreApplication::arguments());
    if (!options) return 2;

    // The tour starts from a clean slate: settings, recovery files and caches in a directory of its own,
    // so neither the user's last session nor an earlier tour shows up in the shots (or is changed by them).
    QTemporaryDir tourHome;
    if (!options->screenshotTourDir.isEmpty() && tourHome.isValid())
        for (const char* name : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"})
            qputenv(name, tourHome.filePath(QString::fromLatin1(name)).toLocal8Bit());

    app::MainWindow window(options->connection.family); // the family's own sample program in the first tab
    if (options->screenshotTourDir.isEmpty()) {
        window.restoreLayout();
        window.connectDrive(options->connection);
        window.show();
        for (const QString& file : options->files) window.editorArea()->documents()->openFile(file);
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
