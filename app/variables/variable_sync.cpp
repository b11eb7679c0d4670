// VariableSync: polls and edits over the DriveSession, in the family's words (VariableRules).
#include "variable_sync.h"

#include "variable_model.h"

namespace app {

namespace {
constexpr int kTickMs = 40;
} // namespace

VariableSync::VariableSync(SessionHost host, VariableModel& model, QObject* parent)
    : QObject(parent), m_host(std::move(host)), m_model(model), m_live(model.rules().liveByDefault()) {
    connect(&m_timer, &QTimer::timeout, this, &VariableSync::poll);
    m_timer.start(kTickMs);
    m_clock.start();
}

void VariableSync::setLive(bool live) {
    m_live = live;
    poll();
}

void VariableSync::follow() {
    serialport::DriveSession* session = m_host.session();
    if (session == m_session) return;
    m_requests.clear();
    m_session = session;
    if (!session) return;
    connect(session, &serialport::DriveSession::answered, this, &VariableSync::onAnswered);
    connect(session, &serialport::DriveSession::lost, this, &VariableSync::onLost);
}

void VariableSync::poll() {
    follow();
    QString reason;
    if (!m_session)
        reason = m_host.notConnected;
    else if (const QString busy = m_host.busyReason(); !busy.isEmpty())
        reason = tr("paused: %1").arg(busy);
    else if (!m_live)
        reason = tr("live values off: Refresh reads the rows in view");
    if (reason != m_pauseReason) {
        m_pauseReason = reason;
        emit pauseReasonChanged(reason);
    }
    const bool busy = !m_requests.isEmpty() || (m_session && !m_session->isReady());
    if (!reason.isEmpty() || busy || !m_wanted || m_clock.elapsed() < m_notBefore) return;
    QStringList wanted;
    for (const QString& name : m_wanted())
        if (m_model.isReadable(name)) wanted << name;
    if (wanted.isEmpty()) return;
    if (m_cursor >= wanted.size()) m_cursor = 0;
    const QStringList batch = wanted.mid(m_cursor, m_model.rules().batch());
    m_cursor += int(batch.size());
    send(m_model.rules().readLine(batch), {Kind::Poll, batch});
}

void VariableSync::read(const QStringList& names, Kind kind) {
    const int batch = m_model.rules().batch();
    for (qsizetype i = 0; i < names.size(); i += batch) {
        const QStringList some = names.mid(i, batch);
        send(m_model.rules().readLine(some), {kind, some});
    }
}

void VariableSync::readNow(const QStringList& names) {
    follow();
    read(names, Kind::ReadBack);
}

void VariableSync::write(const QString& name, const QStringList& lines) {
    follow();
    if (!m_session) {
        emit writeFinished(name, false, tr("Not connected: %1 was not sent.").arg(lines.join(QStringLiteral("; "))));
        return;
    }
    m_refused.remove(name);
    const QString edit = lines.join(QStringLiteral(", ")); // "X1 1234"; "SW1, TGP24, SW0"
    for (qsizetype i = 0; i < lines.size(); ++i) send(lines[i], {Kind::Write, {name}, i == lines.size() - 1, edit});
    read({name}, Kind::ReadBack);
}

quint64 VariableSync::send(const QString& line, Request request) {
    if (!m_session) return 0;
    if (line.isEmpty()) { // the drive has no way to show it
        if (request.kind != Kind::Second)
            for (const QString& name : request.names) m_model.setUnreadable(name);
        return 0;
    }
    request.sentAt = m_clock.elapsed();
    const quint64 id = request.kind == Kind::Write ? m_session->sendLine(line) : m_session->sendQuiet(line);
    m_requests.insert(id, std::move(request));
    return id;
}

void VariableSync::onAnswered(quint64 id, const serialport::LineAnswer& answer) {
    const auto it = m_requests.constFind(id);
    if (it == m_requests.constEnd()) return;
    const Request request = *it;
    m_requests.erase(it);
    const QString& name = request.names.first();
    switch (request.kind) {
    case Kind::Write:
        if (m_refused.contains(name)) break; // said already
        if (!answer.ok()) {
            m_refused.insert(name);
            emit writeFinished(name, false, tr("The drive refused %1: %2").arg(answer.command, answer.error));
        } else if (request.last) {
            emit writeFinished(name, true, tr("%1 sent").arg(request.edit));
        }
        break;
    case Kind::Poll:
    case Kind::ReadBack: applyValues(request.names, answer); break;
    case Kind::Second:
        if (const QStringList values = m_model.rules().values(request.names, answer); values.size() == 1)
            m_model.setSecond(name, values.first());
        break;
    }
    // Leave the link at least half free for the user: wait as long as the exchange took.
    if (request.kind == Kind::Poll)
        m_notBefore = m_clock.elapsed() +
                      std::max<qint64>(m_model.rules().pollIntervalMs(), m_clock.elapsed() - request.sentAt);
    if (m_requests.isEmpty()) emit idle();
}

void VariableSync::onLost(quint64 id, const QString& reason) {
    const auto it = m_requests.constFind(id);
    if (it == m_requests.constEnd()) return;
    const Request request = *it;
    m_requests.erase(it);
    if (request.kind == Kind::Write && !m_refused.contains(request.names.first())) {
        m_refused.insert(request.names.first());
        emit writeFinished(request.names.first(), false, reason);
    }
    if (m_requests.isEmpty()) emit idle();
}

void VariableSync::applyValues(const QStringList& names, const serialport::LineAnswer& answer) {
    const QStringList unreadable = m_model.rules().unreadable(names, answer);
    if (!unreadable.isEmpty()) {
        // Not printed: shown as such and not polled again; the others in the same line are read again.
        for (const QString& name : unreadable) m_model.setUnreadable(name);
        QStringList rest;
        for (const QString& name : names)
            if (m_model.isReadable(name)) rest << name;
        if (!rest.isEmpty()) read(rest, Kind::ReadBack);
        return;
    }
    const QStringList values = m_model.rules().values(names, answer);
    if (values.size() != names.size()) return; // not the answer expected (a program printed meanwhile)
    for (qsizetype i = 0; i < names.size(); ++i) {
        m_model.setValue(names[i], values[i]);
        emit valueRead(names[i], values[i]);
        send(m_model.rules().secondReadLine(names[i]), {Kind::Second, {names[i]}});
    }
}

} // namespace app
