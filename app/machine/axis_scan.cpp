// AxisScan: the BDS5's prompt scan, or one probe per ID through the family's session.
#include "axis_scan.h"

#include "serialport/axis_link.h"
#include "serialport/bds5_bus_scan.h"
#include "serialport/drive_session.h"
#include "serialport/drive_timeout.h"

#include <QTimer>

namespace app::machine {

using drive_core::DriveFamily;

namespace {
// A PMC-960 selected on a bus says nothing; its session asks for a prompt (a CR) 300 ms after its link opens
// (pmc960_session.cpp), so a probe waits that long on top of the axis's own time to answer.
constexpr int kSessionAsksAfterMs = 400;
} // namespace

AxisScan::AxisScan(serialport::Link& line, DriveFamily family, QStringList ids, int waitMs, QObject* parent)
    : QObject(parent), m_line(line), m_family(family), m_ids(std::move(ids)), m_waitMs(waitMs) {}

AxisScan::~AxisScan() {
    m_wait.reset();
    m_session.reset(); // before its link
    m_axis.reset();
}

void AxisScan::start() {
    if (m_family == DriveFamily::Bds5) {
        m_bds5 = std::make_unique<serialport::Bds5BusScan>(m_line, m_ids.join(QString()), m_waitMs);
        connect(m_bds5.get(), &serialport::Bds5BusScan::progress, this, &AxisScan::progress);
        connect(m_bds5.get(), &serialport::Bds5BusScan::finished, this,
                [this](const QList<serialport::Bds5BusScan::Axis>& axes) {
                    for (const auto& a : axes)
                        m_axes.append({QString(a.id), m_family, a.mode + QLatin1Char(' ') + a.prompt});
                    finish();
                });
        QTimer::singleShot(0, m_bds5.get(), &serialport::Bds5BusScan::start);
        return;
    }
    QTimer::singleShot(0, this, &AxisScan::probeNext);
}

void AxisScan::cancel() {
    if (m_bds5) return; // its 36 calls take a few seconds at most: it runs to its end
    m_next = int(m_ids.size());
    endProbe(false);
}

void AxisScan::probeNext() {
    if (m_done) return;
    if (m_next >= m_ids.size()) return finish();
    emit progress(m_next, int(m_ids.size()));
    const QString id = m_ids.at(m_next++);
    m_axis = std::make_unique<serialport::AxisLink>(m_line, m_family, id);
    m_session = serialport::makeDriveSession(m_family, *m_axis);
    m_wait = std::make_unique<serialport::DriveTimeout>(m_line);
    connect(m_wait.get(), &serialport::DriveTimeout::timeout, this, [this] { endProbe(false); });
    connect(m_session.get(), &serialport::DriveSession::readyChanged, this, [this](bool ready) {
        if (ready) endProbe(true);
    });
    m_probing = true;
    m_wait->start(m_waitMs + (m_family == DriveFamily::Pmc960 ? kSessionAsksAfterMs : 0));
    m_axis->open();
}

void AxisScan::endProbe(bool answered) {
    if (!m_probing) return;
    m_probing = false;
    if (answered)
        m_axes.append({m_axis->id(), m_family,
                       m_family == DriveFamily::Sc750 ? QStringLiteral("identified") : QStringLiteral("at its prompt")});
    m_wait->stop();
    // Not from inside the session's own signal: the probe's objects go on the next turn of the loop.
    QTimer::singleShot(0, this, [this] {
        m_wait.reset();
        m_session.reset();
        if (m_axis) m_axis->close();
        m_axis.reset();
        probeNext();
    });
}

void AxisScan::finish() {
    if (m_done) return;
    m_done = true;
    emit finished(m_axes);
}

} // namespace app::machine
