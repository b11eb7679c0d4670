// The PMC-960 session state machine.
#include "pmc960_session.h"

#include "pmc960_timing.h"

#include "drive_core/catalog/pmc960_catalog.h"

#include <QRegularExpression>

#include <algorithm>
#include <utility>

namespace serialport {

namespace {
constexpr char kAttention = 0x1D;
constexpr int kWakeAfterMs = 300; // no prompt yet: send a CR (answers autobaud too, L1806-1826)

// The controller's error codes: # and two hex digits with the high bit set (0x80..0xE3 in the catalog).
// "#00" from a damaged line is text, not error 0 with a message.
const QRegularExpression& errorCodePattern() {
    static const QRegularExpression kPattern(QStringLiteral("#([89A-F][0-9A-F])"));
    return kPattern;
}
} // namespace

Pmc960Session::Pmc960Session(Link& link, QObject* parent) : QObject(parent), m_link(link) {
    qRegisterMetaType<Pmc960Response>();
    m_wake.setSingleShot(true);
    m_wake.setInterval(kWakeAfterMs);
    connect(&m_link, &Link::bytesReceived, this, &Pmc960Session::onBytes);
    connect(&m_link, &Link::opened, this, &Pmc960Session::onLinkOpened);
    connect(&m_link, &Link::closed, this, [this] {
        m_timeout.stop();
        m_wake.stop();
        if (m_current) emit failed(m_current->id, QStringLiteral("link closed"));
        m_pollSettle.stop();
        m_current.reset();
        m_heldTyped.clear();
        m_typedPrompts = 0;
        m_typedPartial = false;
        typedLineClosed();
        setState(State::Closed);
    });
    connect(&m_timeout, &DriveTimeout::timeout, this, &Pmc960Session::onTimeout);
    connect(&m_wake, &QTimer::timeout, this, [this] {
        if (m_state != State::WaitingForPrompt) return;
        askForPrompt();
        m_wake.start();
    });
    m_typedSettle.setSingleShot(true);
    m_typedSettle.setInterval(kTypedSettleMs);
    connect(&m_typedSettle, &QTimer::timeout, this, [this] {
        m_typedPrompts = 0; // the prompt owed is not coming
        typedLineClosed();
        pump();
    });
    m_cutIn.setSingleShot(true);
    connect(&m_cutIn, &QTimer::timeout, this, &Pmc960Session::pump);
    m_lineActive.start();
    m_settle.setSingleShot(true);
    // A link that delivers whole (quietMs 0: in-process, the fuzzer's) needs no settling time.
    m_settle.setInterval(m_link.quietMs() > 0 ? std::max(20, m_link.quietMs() * 4) : 0);
    connect(&m_settle, &QTimer::timeout, this, [this] {
        if (m_state != State::WaitingForPrompt || !endsInPrompt()) return;
        m_buffer.clear();
        m_wake.stop();
        m_resync.clear();
        setState(State::Ready);
        pump();
    });
    m_pollSettle.setSingleShot(true);
    m_pollSettle.setInterval(m_settle.interval());
    connect(&m_pollSettle, &QTimer::timeout, this, [this] {
        if (m_current && m_current->kind == Kind::Poll) takePollAnswer(true);
    });
    connect(&m_statusTimer, &QTimer::timeout, this, [this] {
        if (m_current || m_statusLetters.isEmpty()) return;
        if (typedLineOpen()) {
            // A typed command runs: one status poll at a time, and only once the line is quiet (the tick after).
            const bool queued =
                std::any_of(m_queue.begin(), m_queue.end(), [](const Request& q) { return q.kind == Kind::Poll; });
            if (queued || cutInWaitMs() != 0) return;
        } else if (m_state != State::Ready || !m_queue.empty()) {
            return;
        }
        Request r;
        r.id = m_nextId++;
        r.kind = Kind::Poll;
        r.bytes = QByteArray(1, m_statusLetters.at(m_statusIndex++ % m_statusLetters.size()));
        r.status = true;
        m_queue.push_back(r);
        pump();
    });
    if (m_link.isOpen()) onLinkOpened();
}

QString Pmc960Session::errorText(int code) {
    const auto* info = drive_core::catalog::pmc960::findError(code);
    return info ? QString::fromUtf8(info->message.data(), qsizetype(info->message.size()))
                : QStringLiteral("unknown error");
}

quint64 Pmc960Session::send(const QByteArray& command, int timeoutMs) {
    m_queue.push_back(Request{m_nextId, Kind::Command, command, {}, timeoutMs, false});
    pump();
    return m_nextId++;
}

quint64 Pmc960Session::poll(char letter, int timeoutMs) {
    m_queue.push_back(Request{m_nextId, Kind::Poll, QByteArray(1, letter), {}, timeoutMs, false});
    pump();
    return m_nextId++;
}

quint64 Pmc960Session::sendExpecting(const QByteArray& bytes, const QByteArray& expect, int timeoutMs) {
    m_queue.push_back(Request{m_nextId, Kind::Expect, bytes, expect, timeoutMs, false});
    pump();
    return m_nextId++;
}

void Pmc960Session::sendTyped(const QByteArray& bytes) {
    m_heldTyped += bytes;
    pump();
}

void Pmc960Session::cancelPending() {
    auto queue = std::move(m_queue);
    m_queue.clear();
    for (const Request& r : queue) emit failed(r.id, QStringLiteral("cancelled"));
}

void Pmc960Session::resynchronise(const QByteArray& first) {
    m_timeout.stop();
    m_pollSettle.stop();
    const auto current = std::exchange(m_current, std::nullopt);
    m_inEditor = false;
    m_typedPrompts = 0;
    m_typedPartial = false;
    typedLineClosed();
    m_buffer.clear();
    m_resync = first;
    m_silentAsks = 0;
    setState(State::WaitingForPrompt);
    askForPrompt();
    m_wake.start();
    if (current) emit failed(current->id, QStringLiteral("abandoned to get back to the prompt"));
}

// The ID in a prompt is taken only when three prompts in a row show it: one damaged prompt must not make
// resynchronise() address another axis (<attn><wrong ID> would silence the controller for good).
void Pmc960Session::learnAxisId(char id) {
    if (id == m_axisId) {
        m_axisCandidateSeen = 0;
        return;
    }
    m_axisCandidateSeen = id == m_axisCandidate ? m_axisCandidateSeen + 1 : 1;
    m_axisCandidate = id;
    if (m_axisCandidateSeen >= 3) m_axisId = id;
}

// A CR asks for a prompt; after resynchronise() it is preceded by the bytes asked for and, once the
// controller has stayed silent twice, by <attn><ID> (talker again, in no checksum).
void Pmc960Session::askForPrompt() {
    // Only a controller that stays silent gets <attn><ID>: were the ID learnt wrong, it would deselect one
    // that answers. Silent after any failure, not only a resynchronised download: a damaged byte that
    // arrived as 1DH and another axis's ID deselects the controller, and CRs alone never wake it
    // (serialport.pmc960_download_campaign: a lane left without a prompt for good).
    if (++m_silentAsks > 2) write(QByteArray(1, kAttention) + m_axisId, false);
    if (!m_resync.isEmpty()) write(m_resync, true);
    write("\r", true);
}

void Pmc960Session::setStatusPolling(int intervalMs, const QByteArray& letters) {
    m_statusLetters = letters;
    if (intervalMs <= 0) {
        m_statusTimer.stop();
        return;
    }
    m_statusTimer.start(intervalMs);
}

void Pmc960Session::onLinkOpened() {
    m_buffer.clear();
    setState(State::WaitingForPrompt);
    m_wake.start(); // the power-up prompt may come by itself; if not, a CR asks for one
}

void Pmc960Session::write(const QByteArray& bytes, bool counted) {
    if (counted)
        for (const char c : bytes) m_sentSum = quint16(m_sentSum + quint8(c));
    m_link.write(bytes);
}

void Pmc960Session::setState(State state) {
    if (state == m_state) return;
    m_state = state;
    emit stateChanged(state);
}

void Pmc960Session::pump() {
    if (m_current || m_replaying) return;
    if (!m_heldTyped.isEmpty() && (m_state == State::Ready || m_state == State::Busy)) {
        const QByteArray typed = std::exchange(m_heldTyped, {});
        noteTyped(typed);
        write(typed, true);
        m_lineActive.restart();
    }
    if (m_queue.empty()) return;
    if (typedLineOpen()) {
        // The user's command runs and its prompt is still to come: requests wait for it, but a poll, which the
        // controller answers at once between the steps of whatever it does (5.3.3, L821, L2554), may cut in —
        // so the status panel and Watch Variables follow a routine typed as B<label>.
        const auto poll =
            std::find_if(m_queue.begin(), m_queue.end(), [](const Request& r) { return r.kind == Kind::Poll; });
        if (poll == m_queue.end()) return;
        const int waitMs = cutInWaitMs();
        if (waitMs != 0) {
            if (waitMs > 0) m_cutIn.start(waitMs);
            return;
        }
        m_current = *poll;
        m_current->cutIn = true;
        m_queue.erase(poll);
    } else {
        // Everything waits for the prompt, except that polls and the editor's text need none (the editor
        // gives no prompt until ESC, and a poll is answered at any time).
        const Kind next = m_queue.front().kind;
        if (m_state != State::Ready && !(m_state == State::Busy && (next != Kind::Command || m_inEditor))) return;
        m_current = m_queue.front();
        m_queue.pop_front();
    }
    if (m_current->kind == Kind::Poll) {
        // What came before it stays in the buffer (a prompt still arriving); its answer is looked for after.
        m_pollFrom = m_buffer.size();
        write(QByteArray(1, kAttention) + m_current->bytes, false); // polls are not in the checksum
    } else {
        m_buffer.clear();
        write(m_current->bytes, true);
        setState(State::Busy);
    }
    m_timeout.start(timeoutMsFor(*m_current));
    if (m_current->kind == Kind::Expect && m_current->expect.isEmpty()) complete();
}

// How long a poll still waits before it cuts into the typed command on the line: 0 now, -1 not into this one
// (half typed, a % display, typed bytes held, a poll unanswered already, or the session is not Ready).
int Pmc960Session::cutInWaitMs() const {
    if (m_typedPartial || m_typedPrompts == 0 || m_typedStream || m_cutInUnanswered || !m_heldTyped.isEmpty() ||
        m_state != State::Ready || m_inEditor)
        return -1;
    return int(std::max<qint64>(0, kTypedQuietMs - m_lineActive.elapsed()));
}

bool Pmc960Session::endsInPrompt() const {
    return m_buffer.size() >= 4 && m_buffer.endsWith('}') && m_buffer.at(m_buffer.size() - 4) == '\r' &&
           m_buffer.at(m_buffer.size() - 3) == '\n';
}

void Pmc960Session::onBytes(const QByteArray& bytes) {
    emit rawReceived(bytes);
    m_silentAsks = 0;
    take(bytes);
}

void Pmc960Session::take(const QByteArray& bytes) {
    if (!m_current) {
        emit shownReceived(bytes);
        m_lineActive.restart();
    }
    m_buffer.append(bytes);
    if (!m_current) return takeUnsolicited();
    if (m_current->kind == Kind::Poll) return takePollAnswer(false);
    // The editor's echo ended with a line end yet differs from what was typed: damaged on the wire one
    // way or the other. Said at once rather than after the time-out.
    // An error code on its way (#C1 buffer full: the editor stops and prompts) is not a damaged echo: the
    // prompt that follows ends the request with the controller's own error.
    if (m_current->kind == Kind::Expect && m_current->expect.endsWith("\r\n") && m_buffer.contains("\r\n") &&
        !m_buffer.contains(m_current->expect) && !endsInPrompt() && !m_buffer.contains('#')) {
        const quint64 id = m_current->id;
        m_timeout.stop();
        m_current.reset();
        m_inEditor = true;
        const QByteArray got = std::exchange(m_buffer, {});
        emit failed(id, QStringLiteral("the echo differs: \"%1\"").arg(QString::fromLatin1(got.trimmed())));
        pump();
        return;
    }
    const bool done = (m_current->kind == Kind::Command && endsInPrompt()) ||
                      (m_current->kind == Kind::Expect &&
                       (m_buffer.contains(m_current->expect) || endsInPrompt())); // or an error ended it
    if (done) complete();
}

// Bytes no request of ours waits for: the answers to typed commands, a routine's output, E-codes, prompts.
void Pmc960Session::takeUnsolicited() {
    if (!endsInPrompt()) return;
    learnAxisId(m_buffer.at(m_buffer.size() - 2));
    for (auto it = errorCodePattern().globalMatch(QString::fromLatin1(m_buffer)); it.hasNext();) {
        const int code = it.next().captured(1).toInt(nullptr, 16);
        emit asyncError(code, errorText(code));
    }
    if (m_state == State::WaitingForPrompt) { // more prompts may follow (each CR asked for one)
        // Its errors are reported: only the prompt stays (for the settle check), so the next prompt does not
        // report them again.
        m_buffer = m_buffer.right(4);
        m_settle.start();
        return;
    }
    m_buffer.clear();
    if (m_typedPrompts > 0 && --m_typedPrompts > 0) m_typedSettle.start(); // typed ahead: more prompts owed
    typedLineClosed();
    pump(); // once the user's commands are done, our requests may go
}

// The answer to the poll in flight is "<value> CR" (DECISIONS.md: the controller ends a poll's reply with CR),
// sent the moment the controller reads the poll: after whatever it had sent already — a prompt still on its
// way (a command refused at its sign prompts twice), an error code, a routine's output and closing prompt. Every
// other CR the controller sends is followed by LF (prompts, % samples, listings), so the answer ends at the first
// CR that is not, and begins after the last prompt '}', line feed or #xx code before it; an answer is never
// empty. A CR that is the last byte so far may be a CR LF cut short: while a typed command runs (its routine
// may print and prompt at any time) the answer is taken once no LF has followed for m_pollSettle's time.
void Pmc960Session::takePollAnswer(bool settled) {
    m_pollSettle.stop();
    for (qsizetype cr = m_buffer.indexOf('\r', m_pollFrom); cr >= 0; cr = m_buffer.indexOf('\r', cr + 1)) {
        const bool last = cr + 1 == m_buffer.size();
        if (!last && m_buffer.at(cr + 1) == '\n') continue;
        qsizetype start = m_pollFrom;
        for (qsizetype i = cr - 1; i >= m_pollFrom; --i) {
            if (m_buffer.at(i) == '\n' || m_buffer.at(i) == '}') {
                start = i + 1;
                break;
            }
        }
        const qsizetype hash = cr > 0 ? m_buffer.lastIndexOf('#', cr - 1) : -1;
        if (hash >= start) start = std::min(cr, hash + 3);
        if (start == cr) continue;
        if (last && m_current->cutIn && !settled) return m_pollSettle.start();
        return finishPoll(start, cr);
    }
}

void Pmc960Session::finishPoll(qsizetype start, qsizetype cr) {
    m_timeout.stop();
    m_pollSettle.stop();
    const Request request = *std::exchange(m_current, std::nullopt);
    const QString value = QString::fromLatin1(m_buffer.mid(start, cr - start));
    const QByteArray before = m_buffer.mid(m_pollFrom, start - m_pollFrom);
    const QByteArray after = m_buffer.mid(cr + 1);
    m_buffer.truncate(m_pollFrom);
    // What came with the answer is the controller's own, taken as if the poll had not been on the line: the
    // terminal shows it, a prompt in it ends the typed command, its #xx are reported. No request starts before
    // all of it is taken (bytes that came before our next write cannot be that request's answer).
    m_replaying = true;
    if (!before.isEmpty()) take(before);
    if (!after.isEmpty()) take(after);
    m_replaying = false;
    if (request.status)
        emit statusPolled(request.bytes.at(0), value);
    else
        emit pollAnswered(request.id, request.bytes.at(0), value);
    pump();
}

void Pmc960Session::noteTyped(const QByteArray& bytes) {
    static const QByteArray kEnds("\r?!&\x1b");
    for (const char c : bytes) {
        if (c == '%') m_typedStream = true;
        if (kEnds.contains(c)) {
            m_typedSettle.stop();
            ++m_typedPrompts;
            m_typedPartial = false;
        } else if (c != '\n') {
            m_typedPartial = true;
        }
    }
}

// The user's commands are done (their prompts came, or are forgotten): the next one starts afresh.
void Pmc960Session::typedLineClosed() {
    if (typedLineOpen()) return;
    m_typedStream = false;
    m_cutInUnanswered = false;
}

Pmc960Response Pmc960Session::parse(const Request& request) const {
    Pmc960Response r;
    r.command = request.bytes;
    QByteArray text = m_buffer.left(m_buffer.size() - 4);
    QByteArray echo = request.bytes;
    echo.replace("\r", "");
    if (text.startsWith(echo)) text.remove(0, echo.size());
    r.text = text;
    QString value = QString::fromLatin1(text);
    // The command's own error is its first refusal code; an E-code (ESTOP' in motion, FAULT', ...) that
    // happened to arrive while the command was on the line is the controller's, not the command's.
    for (auto it = errorCodePattern().globalMatch(value); it.hasNext();) {
        const int code = it.next().captured(1).toInt(nullptr, 16);
        if (isAsynchronous(code))
            r.asynchronous.push_back(code);
        else if (r.error == 0)
            r.error = code;
    }
    if (r.error != 0) r.errorText = errorText(r.error);
    value.remove(errorCodePattern());
    r.value = value.trimmed();
    return r;
}

bool Pmc960Session::isAsynchronous(int code) {
    const auto* info = drive_core::catalog::pmc960::findError(code);
    return info && info->asynchronous;
}

void Pmc960Session::complete() {
    m_timeout.stop();
    const Request request = *m_current;
    m_current.reset();
    switch (request.kind) {
    case Kind::Command: {
        m_inEditor = false;
        const Pmc960Response response = parse(request);
        learnAxisId(m_buffer.at(m_buffer.size() - 2));
        m_buffer.clear();
        setState(State::Ready);
        for (const int code : response.asynchronous) emit asyncError(code, errorText(code));
        emit finished(request.id, response);
        break;
    }
    case Kind::Poll: break; // answered in finishPoll()
    case Kind::Expect: {
        Pmc960Response response;
        response.command = request.bytes;
        if (endsInPrompt()) { // the editor ended with an error (#C1 buffer full, ...)
            response = parse(request);
            m_inEditor = false;
            setState(State::Ready);
        } else {
            m_inEditor = true;
        }
        m_buffer.clear();
        for (const int code : response.asynchronous) emit asyncError(code, errorText(code));
        emit finished(request.id, response);
        break;
    }
    }
    pump();
}

int Pmc960Session::timeoutMsFor(const Request& request) const {
    if (request.timeoutMs > 0) return request.timeoutMs;
    const int baud = m_link.baudRate();
    switch (request.kind) {
    case Kind::Command: return Pmc960Timing::commandTimeoutMs(request.bytes, baud);
    case Kind::Poll: return Pmc960Timing::pollTimeoutMs(baud);
    case Kind::Expect: return Pmc960Timing::expectTimeoutMs(request.bytes, request.expect, baud);
    }
    return Pmc960Timing::kCommandMs;
}

void Pmc960Session::onTimeout() {
    if (!m_current) return;
    const int waitedMs = timeoutMsFor(*m_current);
    const quint64 id = m_current->id;
    if (m_current->cutIn) return pollUnanswered();
    m_current.reset();
    setState(State::WaitingForPrompt); // ask for a prompt until one comes
    askForPrompt();
    m_wake.start();
    emit failed(id, QStringLiteral("no answer within %1 ms").arg(waitedMs));
}

// A poll that cut into a running typed command went unanswered. No CR asks for a prompt (it would wait in the
// controller's input and be read as an empty command once the routine ends): the line stays the user's, what
// came meanwhile is the controller's own, and no other poll cuts into this command.
void Pmc960Session::pollUnanswered() {
    const Request request = *std::exchange(m_current, std::nullopt);
    m_pollSettle.stop();
    m_cutInUnanswered = true;
    const QByteArray meanwhile = m_buffer.mid(m_pollFrom);
    m_buffer.truncate(m_pollFrom);
    m_replaying = true;
    if (!meanwhile.isEmpty()) take(meanwhile);
    m_replaying = false;
    emit failed(request.id, QStringLiteral("no answer within %1 ms while the typed command ran; polls wait for its "
                                           "prompt")
                                .arg(timeoutMsFor(request)));
    pump();
}

} // namespace serialport
