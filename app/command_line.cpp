// Command-line parsing for servodesk.
#include "command_line.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

namespace app {

std::optional<LaunchOptions> parseCommandLine(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "app", "ServoDesk, an IDE for programmable servo drives. With no options it "
               "opens connected to a simulated Kollmorgen BDS5."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption tour(
        QStringLiteral("screenshot-tour"),
        QCoreApplication::translate("app", "Save a PNG of every main view into <dir>, then exit."),
        QStringLiteral("dir"));
    const QCommandLineOption port(
        QStringLiteral("port"),
        QCoreApplication::translate("app", "Connect to the drive on serial port or pty <path> "
                                           "instead of the simulator."),
        QStringLiteral("path"));
    const QCommandLineOption baud(
        QStringLiteral("baud"), QCoreApplication::translate("app", "Baud rate, 300 to 19200 (default 9600)."),
        QStringLiteral("rate"), QStringLiteral("9600"));
    const QCommandLineOption drive(
        QStringLiteral("drive"),
        QCoreApplication::translate("app", "The drive family: bds5 (default), sc750 or pmc960."),
        QStringLiteral("family"), QStringLiteral("bds5"));
    parser.addOptions({tour, port, baud, drive});
    parser.process(arguments);

    LaunchOptions options;
    options.screenshotTourDir = parser.value(tour);
    bool ok = false;
    const int rate = parser.value(baud).toInt(&ok);
    if (!ok || !ConnectionChoice::baudRates().contains(rate)) {
        QTextStream(stderr) << "servodesk: --baud must be one of 300, 600, 1200, 2400, 4800, 9600, 19200\n";
        return std::nullopt;
    }
    options.connection.baudRate = rate;
    const auto family = ConnectionChoice::familyFromKey(parser.value(drive));
    if (!family) {
        QTextStream(stderr) << "servodesk: --drive must be bds5, sc750 or pmc960\n";
        return std::nullopt;
    }
    options.connection.family = *family;
    if (parser.isSet(port)) {
        options.connection.kind = ConnectionChoice::Kind::SerialPort;
        options.connection.portName = parser.value(port);
    }
    return options;
}

} // namespace app
