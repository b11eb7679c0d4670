// Command-line parsing for servodesk.
#include "command_line.h"

#include "editing/file_types.h"

#include "serialport/network_link.h"

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
        QCoreApplication::translate("app", "Connect to the drive on serial port or pty <path>, or on a serial "
                                           "device server (tcp://HOST:PORT or rfc2217://HOST:PORT), instead "
                                           "of the simulator."),
        QStringLiteral("path"));
    const QCommandLineOption baud(
        QStringLiteral("baud"), QCoreApplication::translate("app", "Baud rate, 300 to 19200 (default 9600)."),
        QStringLiteral("rate"), QStringLiteral("9600"));
    const QCommandLineOption drive(
        QStringLiteral("drive"),
        QCoreApplication::translate("app", "The drive family: bds5 (default), sc750 or pmc960."),
        QStringLiteral("family"), QStringLiteral("bds5"));
    parser.addOptions({tour, port, baud, drive});
    parser.addPositionalArgument(QStringLiteral("files"),
                                 QCoreApplication::translate("app", "Programs and files to open. Without --drive, "
                                                                    "the first program's extension chooses the "
                                                                    "family (.bas: SC750, .mpl: PMC-960)."),
                                 QStringLiteral("[file...]"));
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
    options.files = parser.positionalArguments();
    // chosen: without --drive, the first file that belongs to one family chooses it, as a double-click on
    // a .bas in a file manager should open the SC750's workspace.
    if (!parser.isSet(drive))
        for (const QString& file : options.files) {
            const FileType type = fileTypeOf(file);
            if (type == FileType::Sc750Program) options.connection.family = drive_core::DriveFamily::Sc750;
            else if (type == FileType::MplProgram) options.connection.family = drive_core::DriveFamily::Pmc960;
            else if (type != FileType::Program && type != FileType::Variables && type != FileType::Capture) continue;
            break;
        }
    if (const QString problem = serialport::NetworkLink::problem(parser.value(port)); !problem.isEmpty()) {
        QTextStream(stderr) << "servodesk: " << problem << "\n";
        return std::nullopt;
    }
    if (parser.isSet(port)) {
        options.connection.kind = ConnectionChoice::Kind::SerialPort;
        options.connection.portName = parser.value(port);
    }
    return options;
}

} // namespace app
