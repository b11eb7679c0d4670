// VariableSync: P polls and edits over the session.
#include "variable_sync.h"

#include "drive_connection.h"
#include "variable_model.h"

#include <QRegularExpression>

namespace app {

namespace {
constexpr int kMinIntervalMs = 150;
constexpr int kCharsPerVariable = 6 + 12; // "NAME " in the echo, a 12-column value in the answer
} // namespace

VariableSync::VariableSync(DriveConnection& connection, VariableModel& model, QObject* parent)
    : QObject(parent), m_connection(connection), m_model(model) {
    connect(&m_timer, &QTimer::timeout, this, &VariableSync::poll);
    m_timer.start(kMinIntervalMs);
    m_clock.start();
}

void VariableSync::setLive(bool live) {
    m_live = live;
    poll();
}

void VariableSync::follow() {
    serialport::Bds5Session* session = m_connection.session();
    if (session == m_session) return;
    m_requests.clear();
    m_session = session;
    if (!session) return;
    connect(session, &serialport::Bds5Session::finished, this, &VariableSync::onFinished);
    connect(session, &serialport::Bds5Session::failed, this, &VariableSync::onFailed);
}

QString VariableSync::pauseReason() const {
    return m_pauseReason;
}

int VariableSync::intervalMsFor(int names) const {
    // Leave the link at least half free for the user: wait as long as the exchange took on the wire.
    const int baud = m_session && m_session->link().baudRate() > 0 ? m_session->link().baudRate() : 115200;
    return std::max(kMinIntervalMs, (names * kCharsPerVariable + 8) * 10 * 1000 / baud);
}

void VariableSync::poll() {
    follow();
    QString reason;
    using Mode = serialport::Bds5Mode;
    if (!m_session || !m_connection.isConnected())
        reason = tr("not connected");
    else if (m_session->mode() == Mode::Running)
        reason = tr("paused: the drive runs a program (no prompt)");
    else if (m_session->mode() != Mode::Interactive && m_session->mode() != Mode::Monitor)
        reason = tr("paused: the drive is at a %1 prompt").arg(serialport::modeName(m_session->mode()));
    else if (!m_live)
        reason = tr("live values off");
    if (reason != m_pauseReason) {
        m_pauseReason = reason;
        emit pauseReasonChanged(reason);
    }
    const bool busy =
        !m_requests.isEmpty() || (m_session && m_session->state() != serialport::Bds5Session::State::Ready);
    if (!reason.isEmpty() || busy || !m_wanted || m_clock.elapsed() < m_notBefore) return;
    QStringList wanted;
    for (const QString& name : m_wanted())
        if (m_model.isReadable(name)) wanted << name;
    if (wanted.isEmpty()) return;
    if (m_cursor >= wanted.size()) m_cursor = 0;
    const QStringList batch = wanted.mid(m_cursor, kBatch);
    m_cursor += int(batch.size());
    send(QStringLiteral("P ") + batch.join(QLatin1Char(' ')), {Kind::Poll, batch});
}

void VariableSync::readNow(const QStringList& names) {
    follow();
    for (qsizetype i = 0; i < names.size(); i += kBatch) {
        const QStringList batch = names.mid(i, kBatch);
        send(QStringLiteral("P ") + batch.join(QLatin1Char(' ')), {Kind::ReadBack, batch});
    }
}

void VariableSync::write(const QString& name, const QString& instruction) {
    follow();
    if (!m_session || !m_connection.isConnected()) {
        emit writeFinished(name, false, tr("Not connected: %1 was not sent.").arg(instruction));
        return;
    }
    send(instruction, {Kind::Write, {name}});
    send(QStringLiteral("P ") + name, {Kind::ReadBack, {name}});
}

quint64 VariableSync::send(const QString& line, Request request) {
    if (!m_session) return 0;
    // Polls and read-backs stay out of the terminal; the user's own writes show there.
    const auto echo = request.kind == Kind::Write ? serialport::Bds5Session::Echo::Shown
                                                  : serialport::Bds5Session::Echo::Quiet;
    const quint64 id = m_session->send(line, echo);
    m_requests.insert(id, std::move(request));
    return id;
}

void VariableSync::onFinished(quint64 id, const serialport::Bds5Response& response) {
    const auto it = m_requests.constFind(id);
    if (it == m_requests.constEnd()) return;
    const Request request = *it;
    m_requests.erase(it);
    switch (request.kind) {
    case Kind::Write:
        if (!response.errors.isEmpty()) {
            const serialport::Bds5ErrorLine& e = response.errors.first();
            const QString said = QStringLiteral("ERR %1 '%2' %3").arg(e.code).arg(e.entry, e.message);
            emit writeFinished(request.names.first(), false,
                               tr("The drive refused %1: %2").arg(response.command, said));
        } else {
            emit writeFinished(request.names.first(), true, tr("%1 sent").arg(response.command));
        }
        break;
    case Kind::Poll:
    case Kind::ReadBack: applyValues(request.names, response); break;
    }
    if (request.kind == Kind::Poll) m_notBefore = m_clock.elapsed() + intervalMsFor(int(request.names.size()));
}

void VariableSync::onFailed(quint64 id, const QString& reason) {
    const auto it = m_requests.constFind(id);
    if (it == m_requests.constEnd()) return;
    const Request request = *it;
    m_requests.erase(it);
    if (request.kind == Kind::Write) emit writeFinished(request.names.first(), false, reason);
}

void VariableSync::applyValues(const QStringList& names, const serialport::Bds5Response& response) {
    if (!response.errors.isEmpty()) {
        // One name the drive cannot print spoils the whole P: drop it and read the others again.
        bool dropped = false;
        for (const serialport::Bds5ErrorLine& e : response.errors)
            if (names.contains(e.entry.toUpper())) {
                m_model.setUnreadable(e.entry.toUpper());
                dropped = true;
            }
        QStringList rest;
        for (const QString& name : names)
            if (m_model.isReadable(name)) rest << name;
        if (dropped && !rest.isEmpty())
            send(QStringLiteral("P ") + rest.join(QLatin1Char(' ')), {Kind::ReadBack, rest});
        return;
    }
    static const QRegularExpression kBlanks(QStringLiteral("\\s+"));
    const QStringList values = response.lines.join(QLatin1Char(' ')).split(kBlanks, Qt::SkipEmptyParts);
    if (values.size() != names.size()) return; // not the answer expected (a program printed meanwhile)
    for (qsizetype i = 0; i < names.size(); ++i) m_model.setValue(names[i], values[i]);
}

} // namespace app
