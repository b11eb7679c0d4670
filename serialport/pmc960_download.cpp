// The PMC-960 program download with checksum verification.
#include "pmc960_download.h"

// Every request's time-out is the session's, derived from the baud rate and the command's time
// (Pmc960Timing): these commands and a line's echo take the controller milliseconds, so a lost answer is
// noticed within a few hundred ms at 9600 baud and the next attempt follows close behind.
namespace serialport {

namespace {
constexpr char kEsc = 0x1B;
constexpr int kBufferFull = 0xC1; // #C1: the program does not fit; another attempt will not change that
constexpr int kPromptBackMs = 10000;
} // namespace

Pmc960Download::Pmc960Download(Pmc960Session& session, const QString& programText, QObject* parent)
    : QObject(parent), m_session(session), m_lines(programLines(programText)) {
    qRegisterMetaType<Pmc960DownloadResult>();
    connect(&m_session, &Pmc960Session::finished, this, &Pmc960Download::onFinished);
    connect(&m_session, &Pmc960Session::pollAnswered, this, &Pmc960Download::onPoll);
    connect(&m_session, &Pmc960Session::failed, this, &Pmc960Download::onFailed);
    m_noPrompt.setSingleShot(true);
    m_noPrompt.setInterval(kPromptBackMs);
    connect(&m_noPrompt, &QTimer::timeout, this, [this] {
        if (m_step == Step::Done) return;
        if (m_step == Step::Cancelling) {
            m_session.cancelPending();
            return finish(false, m_cancelReason + QStringLiteral("; no prompt came back after ESC"));
        }
        finish(false, QStringLiteral("no prompt from the controller %1 s after ESC (attempt %2): it does not answer, "
                                     "or answers another axis ID; the program buffer holds part of the program at most")
                          .arg(kPromptBackMs / 1000)
                          .arg(m_attempt));
        m_session.cancelPending();
    });
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
    m_attempt = 0;
    beginAttempt();
}

void Pmc960Download::beginAttempt() {
    ++m_attempt;
    m_line = 0;
    m_step = Step::ResetChecksum;
    m_waiting = m_session.poll('h'); // waits for the prompt after a resynchronisation
}

// Whatever went wrong part-way, the controller may be in the editor, write-enabled, with part of the
// program: back to the prompt and, while attempts are left, all over again (P{} erases what is there).
void Pmc960Download::attemptFailed(const QString& reason, int error) {
    m_waiting = 0;
    m_session.resynchronise(QByteArray(1, kEsc));
    if (!m_cancelled && error != kBufferFull && m_attempt < kMaxAttempts) {
        emit progress(0, int(m_lines.size()));
        m_noPrompt.start();
        return beginAttempt();
    }
    m_session.send("SW0\r"); // write-protect again; its answer is not waited for
    if (m_cancelled) {
        m_result.cancelled = true;
        return finish(false, QStringLiteral("cancelled"));
    }
    finish(false,
           m_attempt > 1 ? QStringLiteral("%1 (attempt %2 of %2; the program buffer holds part of the program at most)")
                               .arg(reason)
                               .arg(m_attempt)
                         : reason,
           error);
}

void Pmc960Download::cancel() {
    if (m_cancelled || m_step == Step::Done) return;
    m_cancelled = true;
    if (m_attempt == 0) return;                                                  // not started
    const int sent = m_line + (m_step == Step::Lines && m_waiting != 0 ? 1 : 0); // a line in flight may be stored
    m_result.cancelled = true;
    m_cancelReason = QStringLiteral("cancelled (ESC) with %1 of %2 lines sent; the program buffer holds at most those")
                         .arg(sent)
                         .arg(m_lines.size());
    m_waiting = 0; // what is in flight is abandoned, not waited for
    m_step = Step::Cancelling;
    m_session.resynchronise(QByteArray(1, kEsc)); // ESC + CR now
    m_waiting = m_session.send("SW0\r");          // write-protect again once the prompt is back
    m_noPrompt.start();
}

void Pmc960Download::onPoll(quint64 id, char, const QString& value) {
    if (id != m_waiting || m_step == Step::Done) return;
    if (m_step == Step::ResetChecksum) {
        m_noPrompt.stop();
        m_session.resetChecksum(); // the controller's sum restarts at this poll too
        m_step = Step::Enable;
        next();
        return;
    }
    // Verify
    m_result.hostChecksum = m_session.sentChecksum();
    m_result.driveChecksum = quint16(value.toUInt());
    if (m_result.hostChecksum != m_result.driveChecksum)
        return attemptFailed(QStringLiteral("checksum mismatch: sent %1, controller received %2")
                                 .arg(m_result.hostChecksum)
                                 .arg(m_result.driveChecksum));
    finish(true, {});
}

void Pmc960Download::onFinished(quint64 id, const Pmc960Response& response) {
    if (id != m_waiting || m_step == Step::Done) return;
    if (m_step == Step::Cancelling) return finish(false, m_cancelReason);
    if (response.error != 0) return attemptFailed(response.errorText, response.error);
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
    if (id != m_waiting || m_step == Step::Done) return;
    if (m_step == Step::Cancelling)
        return finish(false, m_cancelReason + QStringLiteral("; SW0 not confirmed: ") + reason);
    attemptFailed(reason);
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
    m_noPrompt.stop();
    m_step = Step::Done;
    m_waiting = 0;
    m_result.ok = ok;
    m_result.reason = reason;
    m_result.error = error;
    emit done(m_result);
}

} // namespace serialport
