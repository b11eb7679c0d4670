// AxisLink: one axis of a multidrop line, as a Link of its own (issue 21), so a session, a transfer or a tool
// written for one drive talks to one axis of a bus unchanged. Opening it selects the axis with its family's
// addressing and then says opened(); closing it deselects (where the family has a way) and leaves the line
// open for the next axis. The line (a serial port, a device server, a simulated bus) is shared and not owned:
// one AxisLink at a time may be open on it.
//
// Addressing, by each manual:
//   BDS5     '\' + ID wakes one axis, '\' + a character that is no ID puts all to sleep (L5416-5469, L10013-10038);
//            IDs 0-9, A-Z.
//   SC750    "/nnn" logs unit nnn on; every other unit logs off and stops transmitting (App. C, L3704-L3716);
//            addresses 0-254, sent with three digits so no terminator is needed.
//   PMC-960  <attn><ID> (1DH and the THI ID) makes one axis the talker, the others listeners (L2543-2560);
//            IDs 21H-5AH, one character.
#pragma once

#include "link.h"

#include "drive_core/drive.h"

#include <QPointer>

#include <memory>

namespace serialport {

// The bytes that select axis id of a family's bus; empty when id is no such axis ID (axisIdProblem says why).
QByteArray axisSelectBytes(drive_core::DriveFamily family, const QString& id);
// The bytes that make every axis execute line and none answer, ending with no axis selected; empty when the
// family's line has no broadcast (only the BDS5's: '\*', L5449-5457).
QByteArray axisBroadcastBytes(drive_core::DriveFamily family, const QString& line);
// The bytes that leave no axis selected, empty when the family has none (a logon of another unit does it).
QByteArray axisReleaseBytes(drive_core::DriveFamily family);
// "" when id can be an axis of the family's bus; else why not, with the manual's rule.
QString axisIdProblem(drive_core::DriveFamily family, const QString& id);
// The IDs an axis of the family can have, in the order a scan calls them (SC750: "0" ... "254").
QStringList allAxisIds(drive_core::DriveFamily family);
// A list of IDs as a user writes it: "A,B,D", "ABD" (one-character IDs), ranges "0-31" or "A-H"; empty with
// error set when an ID is not the family's or a range is malformed. Repeats are dropped.
QStringList parseAxisIds(drive_core::DriveFamily family, const QString& text, QString& error);

class AxisLink final : public Link {
    Q_OBJECT
public:
    // line must outlive this link, or be closed (and this link with it) before it goes.
    AxisLink(Link& line, drive_core::DriveFamily family, QString id, QObject* parent = nullptr);
    // The same, keeping the line alive while this link lives (the IDE's axis connections share the Axes panel's).
    AxisLink(std::shared_ptr<Link> line, drive_core::DriveFamily family, QString id, QObject* parent = nullptr);
    ~AxisLink() override;

    const QString& id() const { return m_id; }
    Link& line() const { return *m_line; }
    // Every byte this link put on the line, its selecting and releasing too.
    qint64 bytesWritten() const { return m_written; }

    void open() override;  // opens the line first when it is closed
    void close() override; // releases the axis; the line stays open
    bool isOpen() const override { return m_open; }
    void write(const QByteArray& bytes) override;
    QString description() const override; // "axis B on /dev/ttyUSB0 9600 8N1"
    int baudRate() const override { return m_line->baudRate(); }
    int quietMs() const override { return m_line->quietMs(); }
    std::optional<double> driveClockMs() const override { return m_line->driveClockMs(); }

private:
    void select();
    void put(const QByteArray& bytes);

    std::shared_ptr<Link> m_keep;
    QPointer<Link> m_line;
    drive_core::DriveFamily m_family;
    QString m_id;
    bool m_open = false;
    bool m_opening = false;
    qint64 m_written = 0;
};

} // namespace serialport
