// AxisScan: which axes answer on a multidrop line (issue 21), for every family. A BDS5 line is scanned by
// Bds5BusScan (each ID woken in turn; the prompt names the axis and its mode). The SC750's and the PMC-960's
// axes send nothing when selected, so each ID is selected through an AxisLink and its family's DriveSession is
// given the wait to become ready (the SC750's identification V frame, the PMC-960's prompt); one that does is
// there. The line is left with no axis selected. GUI thread; the line must be open and outlive the scan.
#pragma once

#include "drive_core/drive.h"

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

namespace serialport {
class AxisLink;
class Bds5BusScan;
class DriveSession;
class DriveTimeout;
class Link;
} // namespace serialport

namespace app::machine {

struct FoundAxis {
    QString id;
    drive_core::DriveFamily family = drive_core::DriveFamily::Bds5;
    QString answer; // "interactive B->", "identified", "at its prompt"
};

class AxisScan final : public QObject {
    Q_OBJECT
public:
    // ids: in the order to call them; waitMs: how long a selected ID may take to answer.
    AxisScan(serialport::Link& line, drive_core::DriveFamily family, QStringList ids, int waitMs, QObject* parent = nullptr);
    ~AxisScan() override;

    void start();
    void cancel(); // finished() follows with the axes found so far (a BDS5 scan, seconds long, runs to its end)
    const QList<FoundAxis>& axes() const { return m_axes; }

signals:
    void progress(int called, int total);
    void finished(const QList<app::machine::FoundAxis>& axes); // in call order

private:
    void probeNext();
    void endProbe(bool answered);
    void finish();

    serialport::Link& m_line;
    drive_core::DriveFamily m_family;
    QStringList m_ids;
    int m_waitMs;
    int m_next = 0;
    bool m_done = false;
    bool m_probing = false;
    QList<FoundAxis> m_axes;
    std::unique_ptr<serialport::Bds5BusScan> m_bds5;
    std::unique_ptr<serialport::AxisLink> m_axis;
    std::unique_ptr<serialport::DriveSession> m_session;
    std::unique_ptr<serialport::DriveTimeout> m_wait;
};

} // namespace app::machine
