// The PMC-960 program download with checksum verification.
#include "pmc960_download.h"

namespace serialport {

Pmc960Download::Pmc960Download(Pmc960Session& session, const QString& programText, QObject* parent)
    : QObject(parent), m_session(session), m_lines(programLines(programText)) {
    qRegisterMetaType<Pmc960DownloadResult>();
    connect(&m_session, &Pmc960Session::finished, this, &Pmc960Download::onFinished);
    connect(&m_session, &Pmc960Session::pollAnswered, this, &Pmc960Download::onPoll);
    connect(&m_session, &Pmc960Session::failed, this, &Pmc960Download::onFailed);
}

QStringList Pmc960Download::programLines(const QString& text) {
    QStringList lines;
    QString normal = text;
    normal.replace(QStringLiteral("\r\n"), QStringLiteral("\n")).replace(QLatin1Char('\r'), QLatin1Char('\n'));
    for (QString line : normal.split(QLatin1Char('\n'))) {
        line.remove(QLatin1Char(' ')).remove(QLatin1Char('\t')); // spaces are not stored (L1412)
        if (!line.isEmpty()) lines << line;
    }
    return lines;
}

void Pmc960Download::start() {
    m_step = Step::ResetChecksum;
    m_waiting = m_session.poll('h');
}

void Pmc960Download::cancel() {
    m_cancelled = true;
}

void Pmc960Download::onPoll(quint64 id, char, const QString& value) {
    if (id != m_waiting) return;
    if (m_step == Step::ResetChecksum) {
        m_session.resetChecksum(); // the controller's sum restarts at this poll too
        m_step = Step::Enable;
        next();
        return;
    }
    // Verify
    m_result.hostChecksum = m_session.sentChecksum();
    m_result.driveChecksum = quint16(value.toUInt());
    if (m_result.hostChecksum != m_result.driveChecksum)
        return finish(false, QStringLiteral("checksum mismatch: sent %1, controller received %2")
                                 .arg(m_result.hostChecksum)
                                 .arg(m_result.driveChecksum));
    finish(true, {});
}

void Pmc960Download::onFinished(quint64 id, const Pmc960Response& response) {
    if (id != m_waiting) return;
    if (response.error != 0) {
        if (m_step == Step::Leave || m_step == Step::Protect) m_session.send("SW0\r");
        return finish(false, response.errorText, response.error);
    }
    switch (m_step) {
    case Step::Enable: m_step = Step::Erase; break;
    case Step::Erase: m_step = Step::Enter; break;
    case Step::Enter: m_step = Step::Lines; break;
    case Step::Lines:
        ++m_line;
        emit progress(m_line, int(m_lines.size()));
        break;
    case Step::Leave: m_step = Step::Protect; break;
    case Step::Protect: m_step = Step::Verify; break;
    default: break;
    }
    next();
}

void Pmc960Download::onFailed(quint64 id, const QString& reason) {
    if (id != m_waiting) return;
    finish(false, reason);
}

void Pmc960Download::next() {
    if (m_cancelled && (m_step == Step::Lines || m_step == Step::Enter)) {
        m_result.cancelled = true;
        m_step = Step::Leave;
    }
    switch (m_step) {
    case Step::Enable: m_waiting = m_session.send("SW1\r"); return;
    case Step::Erase: m_waiting = m_session.send("P{}"); return; // } in column 1 erases to the end (L930)
    case Step::Enter: m_waiting = m_session.sendExpecting("P\r", "P"); return;
    case Step::Lines:
        if (m_line < m_lines.size()) {
            const QByteArray line = m_lines.at(m_line).toLatin1();
            m_waiting = m_session.sendExpecting(line + '\r', line + "\r\n");
            return;
        }
        m_step = Step::Leave;
        [[fallthrough]];
    case Step::Leave: m_waiting = m_session.send("\x1b"); return;
    case Step::Protect: m_waiting = m_session.send("SW0\r"); return;
    case Step::Verify:
        if (m_result.cancelled) return finish(false, QStringLiteral("cancelled"));
        m_waiting = m_session.poll('h');
        return;
    default: return;
    }
}

void Pmc960Download::finish(bool ok, const QString& reason, int error) {
    m_step = Step::Done;
    m_waiting = 0;
    m_result.ok = ok;
    m_result.reason = reason;
    m_result.error = error;
    emit done(m_result);
}

} // namespace serialport
