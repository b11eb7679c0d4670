// A Link carries bytes between the IDE and one drive: a serial port, a pty, or a simulated drive.
// Everything above it (sessions, terminal) sees only bytes, so a simulator and a real drive are alike.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

#include <optional>

namespace serialport {

class Link : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~Link() override = default;

    // Opens asynchronously; emits opened() or errorOccurred(). GUI thread only.
    virtual void open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // Queues bytes for the drive. Ignored (with errorOccurred) when the link is closed.
    virtual void write(const QByteArray& bytes) = 0;
    // For the status bar: "Simulated BDS5", "/dev/ttyUSB0 9600 8N1".
    virtual QString description() const = 0;
    // Bits per second on the wire, 0 when not limited; sessions derive their time-outs from it.
    virtual int baudRate() const = 0;
    // How long the line must stay quiet after a prompt-shaped tail before a session trusts it is a prompt
    // (§2.10 rule 6). USB serial adapters deliver in bursts up to 16 ms apart (FTDI latency timer).
    virtual int quietMs() const { return 20; }
    // The drive's own clock in ms where the link has one (a simulated drive, whose thread a loaded host can
    // stall); none for a real port. Sessions count their time-outs in it (drive_timeout.h). Any thread.
    virtual std::optional<double> driveClockMs() const { return std::nullopt; }

signals:
    void opened();
    void closed();
    void bytesReceived(const QByteArray& bytes);
    // A human-readable reason: the port vanished, could not be opened, a write failed.
    void errorOccurred(const QString& message);
};

} // namespace serialport
