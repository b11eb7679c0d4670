// Which drive the IDE talks to: its family (BDS5, SC750, PMC-960) and the built-in simulated drive of that
// family or a serial port (a real drive or a pty).
// A value type, remembered in QSettings, that knows how to create the matching Link.
#pragma once

#include "drive_core/drive.h"
#include "serialport/link.h"

#include <QList>
#include <QString>

#include <memory>
#include <optional>

class QSettings;

namespace app {

struct ConnectionChoice {
    enum class Kind { Simulator, SerialPort };

    Kind kind = Kind::Simulator;
    QString portName;    // "/dev/ttyUSB0", "ttyS0", "/dev/pts/5"; used when kind is SerialPort
    int baudRate = 9600; // the serial port's rate, or the pace of the simulated drive's output
    drive_core::DriveFamily family = drive_core::DriveFamily::Bds5;
    // One axis of a multidrop line (issue 21): the line the Axes panel holds open, and the axis's ID on it.
    // makeLink() then gives an AxisLink that selects the axis; the line stays open when the IDE moves to
    // another axis. Neither is saved: a line is the panel's, set up again each session.
    std::shared_ptr<serialport::Link> line;
    QString axis;

    static ConnectionChoice onAxis(std::shared_ptr<serialport::Link> line, drive_core::DriveFamily family,
                                   const QString& axis) {
        ConnectionChoice c;
        c.family = family;
        c.line = std::move(line);
        c.axis = axis;
        return c;
    }

    static ConnectionChoice simulator(drive_core::DriveFamily family = drive_core::DriveFamily::Bds5) {
        ConnectionChoice c;
        c.family = family;
        return c;
    }
    static ConnectionChoice serialPort(const QString& port, int baud) {
        return {Kind::SerialPort, port, baud};
    }

    // "BDS5", "SC750", "PMC-960" (the status bar, the dialog) and the settings/command-line keys
    // "bds5", "sc750", "pmc960".
    static QString familyName(drive_core::DriveFamily family);
    static QString familyKey(drive_core::DriveFamily family);
    static std::optional<drive_core::DriveFamily> familyFromKey(const QString& key);

    // The rates the BDS5 supports (seed-bds5 §2.1).
    static QList<int> baudRates() { return {300, 600, 1200, 2400, 4800, 9600, 19200}; }

    // Settings live under "connection/"; a missing or damaged entry gives the default (the simulator).
    static ConnectionChoice load(QSettings& settings);
    void save(QSettings& settings) const;

    // A new, unopened link for this choice.
    std::unique_ptr<serialport::Link> makeLink() const;
    // For the status bar: "Simulated BDS5, 9600 baud", "/dev/pts/5, 9600 baud", "axis B on /dev/pts/5 9600 8N1".
    QString portText() const;

    bool operator==(const ConnectionChoice&) const = default;
};

} // namespace app
