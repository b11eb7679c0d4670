// MoveWatch: the plan's answers and the drive's own error lines, while a recording runs.
#include "move_watch.h"

#include "families/bds5/bds5_error_text.h"

#include <QTimer>

#include <utility>

namespace app {

namespace {
using serialport::Bds5ErrorLine;
using State = serialport::Bds5Session::State;

constexpr int kMaxLine = 256; // a longer line without CR LF is not an error message
// The drive's own faults (App. D.2.2 and D.2.3, ERR 10-27: over-current, MOTION input, software and hardware
// overtravel, PE overflow, ...). No command answers with them, so they mean the move was cut short wherever
// they show, even inside another command's answer; other errors only when the drive printed them unasked.
bool isFault(int code) {
    return code >= 10 && code <= 27;
}

// "ERR 50 DRIVE INHIBITED": the offending entry only when it is not simply the command itself.
QString errorText(const Bds5ErrorLine& e, const QString& command = {}) {
    QString text = QStringLiteral("ERR %1").arg(e.code);
    if (e.programLine > 0) text += QStringLiteral(" LINE %1").arg(e.programLine);
    if (!e.entry.isEmpty() && e.entry.compare(command, Qt::CaseInsensitive) != 0)
        text += QStringLiteral(" '%1'").arg(e.entry);
    return text + QLatin1Char(' ') + e.message;
}
} // namespace

MoveWatch::MoveWatch(serialport::Bds5Session& session, serialport::Bds5RecordPlay& record)
    : QObject(&record), m_session(&session), m_record(record), m_recordLine(record.plan().recordLine()) {
    for (const auto& c : record.plan().commands) m_commands << c.line.trimmed();
    connect(&session, &serialport::Bds5Session::finished, this, &MoveWatch::onAnswer);
    connect(&session, &serialport::Bds5Session::rawReceived, this, &MoveWatch::onBytes);
    // Held errors come between the echo of the command they made the drive ignore and the next prompt.
    connect(&session, &serialport::Bds5Session::stateChanged, this, [this](State state) {
        if (state == State::Ready) m_held = false;
    });
}

// The plan's own commands: an error in the answer is the drive refusing the move (ERR 50 drive disabled,
// ERR 19 MOTION off, ERR 83 a value out of range, ...). RECORD's and PLAY's errors are Bds5RecordPlay's.
void MoveWatch::onAnswer(quint64, const serialport::Bds5Response& response) {
    if (!m_reason.isEmpty() || !m_record.isRunning()) return;
    const QString line = response.command.trimmed();
    if (line.compare(m_recordLine, Qt::CaseInsensitive) == 0) {
        m_recording = response.errors.isEmpty();
        return;
    }
    if (!m_recording || !m_commands.contains(line, Qt::CaseInsensitive)) return;
    if (response.errors.isEmpty()) {
        m_moving = line;
        return;
    }
    const Bds5ErrorLine& e = response.errors.first();
    m_reason =
        isFault(e.code)
            ? tr("the drive reported %1 during %2 \u2014 %3")
                  .arg(errorText(e, line), line, Bds5ErrorText::fixHint(e.code))
            : tr("the drive refused %1: %2 \u2014 %3").arg(line, errorText(e, line), Bds5ErrorText::fixHint(e.code));
    m_record.abort(summary());
}

// The drive's error lines start with a bell (L6036-6060). Between the plan's commands the drive sits at its
// prompt and holds a fault until the next line comes; it then prints ERROR MSG WAITING--COMMAND IGNORED and
// the held errors (L9721-9739), which the session answers by sending the command again: only this stream
// shows them.
void MoveWatch::onBytes(const QByteArray& bytes) {
    for (const char c : bytes) {
        if (c != '\r' && c != '\n') {
            if (m_line.size() < kMaxLine) m_line.append(c);
            continue;
        }
        onLine(std::exchange(m_line, {}));
    }
}

void MoveWatch::onLine(const QByteArray& line) {
    if (line.contains("MSG WAITING")) {
        m_held = true;
        return;
    }
    const qsizetype bell = line.lastIndexOf('\a');
    if (bell < 0 || !m_recording || !m_reason.isEmpty() || !m_record.isRunning()) return;
    const auto error = serialport::parseErrorLine(QString::fromLatin1(line.mid(bell)));
    if (!error) return;
    // Inside a command's answer an ordinary error belongs to that command: onAnswer judges the plan's, and
    // Bds5RecordPlay takes one inside PLAY's listing for damage on the wire.
    const bool unasked = !m_session || m_session->state() != State::Busy;
    if (!m_held && !unasked && !isFault(error->code)) return;
    m_reason = tr("the drive reported %1 during %2 \u2014 %3")
                   .arg(errorText(*error), m_moving.isEmpty() ? tr("the recording") : m_moving,
                        Bds5ErrorText::fixHint(error->code));
    // Not from inside the session's byte handler: the abort may write to the drive (Esc during PLAY).
    QTimer::singleShot(0, this, [this] { m_record.abort(summary()); });
}

QString MoveWatch::summary() const {
    return m_reason.isEmpty() ? QString() : tr("Record stopped: %1 Nothing was read back or shown.").arg(m_reason);
}

} // namespace app
