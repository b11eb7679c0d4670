// The BDS5 session state machine.
#include "bds5_session.h"

namespace serialport {

namespace {
constexpr int kTailKeep = 256;
constexpr int kWakeAfterMs = 600;    // no prompt this long after opening: send a CR to ask for one
constexpr int kRunDetectMs = 1500;   // no prompt this long after a typed line: run mode (EN takes seconds)
const QString kIgnored = QStringLiteral("ERROR MSG WAITING--COMMAND IGNORED");
} // namespace

Bds5Session::Bds5Session(Link& link, QObject* parent) : QObject(parent), m_link(link) {
    qRegisterMetaType<Bds5Response>();
    m_silence.setSingleShot(true);
    m_silence.setInterval(m_link.quietMs());
    m_wake.setSingleShot(true);
    m_wake.setInterval(kWakeAfterMs);
    connect(&m_link, &Link::bytesReceived, this, &Bds5Session::onBytes);
    connect(&m_link, &Link::opened, this, &Bds5Session::onLinkOpened);
    connect(&m_link, &Link::closed, this, &Bds5Session::onLinkClosed);
    m_runDetect.setSingleShot(true);
    m_runDetect.setInterval(kRunDetectMs);
    connect(&m_runDetect, &QTimer::timeout, this, [this] {
        if (m_state != State::WaitingForPrompt || m_mode == Bds5Mode::Running) return;
        m_mode = Bds5Mode::Running;
        m_prompt.clear();
        emit modeChanged(m_mode, m_prompt);
    });
    connect(&m_silence, &QTimer::timeout, this, &Bds5Session::onPromptConfirmed);
    connect(&m_timeout, &DriveTimeout::timeout, this, &Bds5Session::onTimeout);
    connect(&m_wake, &QTimer::timeout, this, [this] {
        if (m_state != State::WaitingForPrompt || m_rawLineOpen) return;
        write("\r");
        // After a time-out the CR or the prompt it asked for may be lost too: keep asking, or the queue
        // would wait for ever.
        if (m_resyncing) m_wake.start();
    });
    if (m_link.isOpen()) onLinkOpened();
}

quint64 Bds5Session::send(const QString& line, Echo echo) {
    const quint64 id = m_nextId++;
    m_queue.push_back(Pending{id, line, 1, {}, echo == Echo::Quiet});
    pump();
    return id;
}

quint64 Bds5Session::sendEscape() {
    const quint64 id = m_nextId++;
    m_queue.push_back(Pending{id, QString(), 0, QByteArray("\x1b")});
    pump();
    return id;
}

void Bds5Session::sendRaw(const QByteArray& bytes) {
    // Terminal bytes wait while queued commands run (a download's lines must not get typing mixed in). A
    // sleeping multidrop drive runs nothing: what the user sends then (its wake-up) goes out at once.
    if ((m_current || !m_queue.empty()) && m_mode != Bds5Mode::Asleep) {
        m_heldRaw.append(bytes);
        return;
    }
    passRaw(bytes);
}

void Bds5Session::sendUrgent(const QByteArray& bytes) {
    // With a command in flight its response still ends at the drive's next prompt; nothing else changes.
    if (m_current) write(bytes);
    else passRaw(bytes);
    if (bytes.contains('\x18')) emit stopSent();
}

void Bds5Session::passRaw(const QByteArray& bytes) {
    if (!m_link.isOpen()) return; // nothing to type into; the state stays Closed
    // A multidrop wake-up (a backslash and the ID, L5449-5451) addresses the line; it types nothing into one.
    for (qsizetype i = 0; i < bytes.size(); ++i) {
        const char c = bytes.at(i);
        if (c == '\\') ++i;
        else if (c == '\r' || c == '\x1b' || c == '\x18') m_rawLineOpen = false;
        else if (c >= ' ') m_rawLineOpen = true;
    }
    if (bytes.contains('\r') || bytes.contains('\x1b')) {
        setState(State::WaitingForPrompt);
        // No prompt soon after a line the user typed: the drive runs a program (run mode has no prompt).
        // Nothing is sent to ask: a CR could answer a program's INPUT.
        m_runDetect.start();
    }
    write(bytes);
}

void Bds5Session::cancelPending() {
    std::deque<Pending> dropped;
    dropped.swap(m_queue);
    for (const Pending& p : dropped) emit failed(p.id, tr("cancelled before it was sent"));
}

void Bds5Session::onLinkOpened() {
    m_tail.clear();
    m_linkTroubles = 0;
    setState(State::WaitingForPrompt);
    m_wake.start();
}

void Bds5Session::onLinkClosed() {
    m_silence.stop();
    m_timeout.stop();
    m_wake.stop();
    m_resyncing = false;
    m_mode = Bds5Mode::Unknown;
    // Closed before anyone hears of the failure, so no one reacting to it (a download starting again)
    // takes the session for one that will answer.
    setState(State::Closed);
    const auto current = std::move(m_current);
    m_current.reset();
    if (current) emit failed(current->id, tr("the link closed before the drive answered"));
    cancelPending();
}

void Bds5Session::onBytes(const QByteArray& bytes) {
    emit rawReceived(bytes);
    if (!m_current || !m_current->quiet) emit shownReceived(bytes);
    const QString text = QString::fromLatin1(bytes);
    m_tail = (m_tail + text).right(kTailKeep);
    if (m_current) {
        m_response += text;
        // The time-out counts from the last byte: a long <BDS or DUMP listing at 9600 baud outlasts any
        // fixed allowance, yet a drive that has stopped talking is still noticed.
        m_timeout.start(timeoutMsFor(m_current->line));
    }
    // A prompt counts only when it ends the stream and the drive then stays silent (§2.10 rule 6). In
    // program-load mode nothing but the echo comes before the l-> prompt: it counts at once, which keeps
    // a download at the wire's pace.
    if (addressEchoEndingIn(m_tail)) return fallAsleep();
    const auto prompt = trailingPrompt(m_tail);
    if (prompt && m_current && modeOfPrompt(*prompt) == Bds5Mode::ProgramLoad) {
        m_silence.stop();
        return onPromptConfirmed();
    }
    if (prompt) m_silence.start();
    else m_silence.stop();
}

// "-->TRC OFF": the drive printed a prompt of its own (a program ending, trace) just before the echo. The
// answer is whole; nothing was damaged on the wire.
bool Bds5Session::strayPromptBeforeEcho(const QString& text, const QString& line) {
    const qsizetype at = text.indexOf(line + QStringLiteral("\r\n"));
    return at > 0 && at <= 8 && text.left(at).endsWith(QLatin1Char('>'));
}

void Bds5Session::onPromptConfirmed() {
    const auto prompt = trailingPrompt(m_tail);
    if (!prompt) return;
    m_wake.stop();
    m_runDetect.stop();
    m_resyncing = false;
    if (*prompt != m_prompt || modeOfPrompt(*prompt) != m_mode) {
        m_prompt = *prompt;
        m_mode = modeOfPrompt(*prompt);
        emit modeChanged(m_mode, m_prompt);
    }
    if (m_current) {
        m_timeout.stop();
        Pending done = *m_current;
        m_current.reset();
        Bds5Response response = parseResponse(done, std::exchange(m_response, {}), *prompt);
        m_linkTroubles += response.garbled && !strayPromptBeforeEcho(response.text, done.line);
        if (response.ignored && done.retries > 0) { // the drive flushed a held error: send it again (rule 3)
            --done.retries;
            m_queue.push_front(done);
        } else {
            emit finished(done.id, response);
        }
    }
    setState(State::Ready);
    if (!m_heldRaw.isEmpty() && m_queue.empty()) sendRaw(std::exchange(m_heldRaw, {}));
    pump();
}

// The drive echoed a line that gave it a multidrop address: it now sleeps until "\\" + its ID and sends no
// prompt (L5449-5451). The command is done; queued commands wait for the prompt the wake-up brings, and a
// held wake-up goes out now. (Rewriting the address a drive already has is answered with a prompt, which
// ends the sleep at once.)
void Bds5Session::fallAsleep() {
    m_timeout.stop();
    m_silence.stop();
    m_runDetect.stop();
    m_wake.stop();
    m_resyncing = false;
    m_rawLineOpen = false;
    setState(State::WaitingForPrompt);
    if (m_mode != Bds5Mode::Asleep) {
        m_mode = Bds5Mode::Asleep;
        m_prompt.clear();
        emit modeChanged(m_mode, m_prompt);
    }
    if (m_current) {
        const Pending done = *m_current;
        m_current.reset();
        emit finished(done.id, parseResponse(done, std::exchange(m_response, {}), QString()));
    }
    if (!m_heldRaw.isEmpty()) passRaw(std::exchange(m_heldRaw, {}));
}

void Bds5Session::onTimeout() {
    if (!m_current) return;
    const Pending lost = *m_current;
    m_current.reset();
    m_response.clear();
    setState(State::WaitingForPrompt);
    emit failed(lost.id, tr("no prompt from the drive within %1 ms after \"%2\"")
                             .arg(timeoutMsFor(lost.line))
                             .arg(lost.line));
    write("\r"); // ask for a prompt so the queue can go on
    m_resyncing = true;
    ++m_linkTroubles;
    m_wake.start();
}

void Bds5Session::pump() {
    if (m_current || m_queue.empty() || m_state != State::Ready || m_rawLineOpen) return;
    m_current = m_queue.front();
    m_queue.pop_front();
    m_response.clear();
    setState(State::Busy);
    m_timeout.start(timeoutMsFor(m_current->line));
    write(m_current->bytes.isEmpty() ? m_current->line.toLatin1() + '\r' : m_current->bytes);
}

void Bds5Session::write(const QByteArray& bytes) {
    emit rawSent(bytes);
    m_link.write(bytes);
}

void Bds5Session::setState(State state) {
    if (state == m_state) return;
    m_state = state;
    emit stateChanged(state);
}

int Bds5Session::timeoutMsFor(const QString& line) const {
    // The time-out restarts with every byte received: it covers the command crossing the wire, its echo
    // and prompt coming back (10 bits a character), and the drive's own command time.
    const int baud = m_link.baudRate() > 0 ? m_link.baudRate() : 115200;
    const int chars = 2 * int(line.size()) + 16;
    return bds5CommandSilenceMs(line, m_mode) + chars * 10 * 1000 / baud;
}

Bds5Response Bds5Session::parseResponse(const Pending& command, QString text, const QString& prompt) const {
    Bds5Response r;
    r.command = command.line;
    r.prompt = prompt;
    text.chop(prompt.size());
    const QString echo = command.line + QStringLiteral("\r\n");
    if (text.startsWith(echo)) text.remove(0, echo.size());
    else if (text.startsWith(QStringLiteral("\r\n"))) text.remove(0, 2); // ECHO 0: only the line end
    else r.garbled = !command.line.isEmpty();
    r.text = text;
    for (QString line : text.split(QStringLiteral("\r\n"))) {
        while (line.startsWith(QLatin1Char('\n'))) line.remove(0, 1);
        if (line.isEmpty()) continue;
        if (line == kIgnored) r.ignored = true;
        else if (const auto error = parseErrorLine(line)) r.errors.append(*error);
        else r.lines.append(line);
    }
    return r;
}

} // namespace serialport
