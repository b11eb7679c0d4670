// servodesk-cli: ServoDesk without windows — check, download, upload, variables, send, run, stop, record
// and watch against a simulated drive (the default) or a drive on a serial port.
#include "cli/cli_options.h"
#include "cli/cli_runner.h"

#include <QCoreApplication>

#include <cstdio>

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("servodesk-cli"));
    QString error;
    const auto options = app::cli::parseCliOptions(QCoreApplication::arguments().mid(1), error);
    if (!options) {
        std::fprintf(stderr, "servodesk-cli: %s\n%s", qPrintable(error), qPrintable(app::cli::cliUsage()));
        return app::cli::CliRunner::kUsage;
    }
    if (options->help) {
        std::fputs(qPrintable(app::cli::cliUsage()), stdout);
        return 0;
    }
    app::cli::CliRunner runner(*options);
    QObject::connect(&runner, &app::cli::CliRunner::done, &application, &QCoreApplication::exit, Qt::QueuedConnection);
    runner.start();
    return QCoreApplication::exec();
}
