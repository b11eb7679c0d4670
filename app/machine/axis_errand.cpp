// AxisErrand: select, do, release.
#include "axis_errand.h"

#include "serialport/axis_link.h"
#include "serialport/drive_session.h"
#include "serialport/drive_timeout.h"

#include <QTimer>

namespace app::machine {

namespace {
constexpr int kSelectTimeoutMs = 5000; // as MachineJob's
}

AxisErrand::AxisErrand(serialport::Link& line, drive_core::DriveFamily family, QString id, QObject* parent)
    : QObject(parent), m_line(line), m_family(family), m_id(std::move(id)) {}

AxisErrand::~AxisErrand() {
    m_wait.reset();
    m_session.reset();
    if (m_axis) m_axis->close();
}

void AxisErrand::sendLines(const QStringList& lines) {
    m_lines = lines;
    begin();
}

void AxisErrand::download(const QString& programText) {
    m_program = programText;
    m_downloading = true;
    begin();
}

void AxisErrand::begin() {
    m_axis = std::make_unique<serialport::AxisLink>(m_line, m_family, m_id);
    m_session = serialport::makeDriveSession(m_family, *m_axis);
    m_wait = std::make_unique<serialport::DriveTimeout>(m_line);
    connect(m_wait.get(), &serialport::DriveTimeout::timeout, this, [this] {
        finish(false, tr("no answer from axis %1; nothing was changed").arg(m_id));
    });
    connect(m_session.get(), &serialport::DriveSession::readyChanged, this, [this](bool ready) {
        if (ready && !m_started) onReady();
    });
    connect(m_session.get(), &serialport::DriveSession::linkFailed, this, [this](const QString& why) { finish(false, why); });
    connect(m_session.get(), &serialport::DriveSession::answered, this,
            [this](quint64 id, const serialport::LineAnswer& a) {
                if (id != m_pending) return;
                if (!a.ok()) return finish(false, tr("axis %1 refused \"%2\": %3").arg(m_id, a.command, a.error));
                m_answers << a.lines.join(QLatin1Char(' '));
                nextLine();
            });
    connect(m_session.get(), &serialport::DriveSession::lost, this, [this](quint64 id, const QString& why) {
        if (id == m_pending) finish(false, tr("axis %1 did not answer \"%2\": %3").arg(m_id, m_current, why));
    });
    connect(m_session.get(), &serialport::DriveSession::transferFinished, this,
            [this](const serialport::TransferResult& r) { finish(r.ok(), r.ok() ? r.message : r.message + QLatin1Char(' ') + r.driveHolds); });
    m_wait->start(kSelectTimeoutMs);
    m_axis->open();
}

void AxisErrand::onReady() {
    m_started = true;
    m_wait->stop();
    if (m_downloading) return m_session->download(m_program);
    nextLine();
}

void AxisErrand::nextLine() {
    if (m_lines.isEmpty()) return finish(true, tr("axis %1 took it").arg(m_id));
    m_current = m_lines.takeFirst();
    m_pending = m_session->sendLine(m_current);
}

void AxisErrand::finish(bool ok, const QString& message) {
    if (m_done) return;
    m_done = true;
    if (m_wait) m_wait->stop();
    QTimer::singleShot(0, this, [this, ok, message] { emit finished(ok, message); });
}

} // namespace app::machine
