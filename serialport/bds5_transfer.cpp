// Bds5Transfer: one command at a time on the session, filtered by id, with line counting for progress.
#include "bds5_transfer.h"

#include <QTimer>

namespace serialport {

Bds5Transfer::Bds5Transfer(Bds5Session& session, QObject* parent) : QObject(parent), m_session(&session) {
    qRegisterMetaType<Bds5TransferResult>();
    connect(&session, &Bds5Session::finished, this, &Bds5Transfer::onFinished);
    connect(&session, &Bds5Session::failed, this, &Bds5Transfer::onFailed);
    connect(&session, &Bds5Session::rawReceived, this, &Bds5Transfer::onRaw);
    // The connection may be replaced mid-transfer: the session goes away with its link.
    connect(&session, &QObject::destroyed, this, [this] {
        if (m_running) lost(tr("the connection to the drive was closed"));
    });
}

Bds5Transfer::~Bds5Transfer() = default;

void Bds5Transfer::start() {
    if (m_running) return;
    m_running = true;
    m_cancelled = false;
    QTimer::singleShot(0, this, [this] {
        if (!m_session) return lost(tr("there is no connection to a drive"));
        begin();
    });
}

void Bds5Transfer::cancel() {
    m_cancelled = true;
}

void Bds5Transfer::send(const QString& line) {
    m_counting = false;
    m_pending = m_session->send(line);
}

void Bds5Transfer::sendEscape() {
    m_counting = false;
    m_pending = m_session->sendEscape();
}

void Bds5Transfer::countLinesInto(int base, int total) {
    m_counting = true;
    m_countBase = base;
    m_countTotal = total;
    m_counted = -1; // the echo's line end comes first
}

bool Bds5Transfer::sessionAtInteractivePrompt() const {
    return m_session && m_session->mode() == Bds5Mode::Interactive &&
           m_session->state() != Bds5Session::State::Closed;
}

void Bds5Transfer::finish(Bds5TransferResult result) {
    if (!m_running) return;
    m_running = false;
    m_pending.reset();
    m_counting = false;
    emit finished(result);
}

void Bds5Transfer::onFinished(quint64 id, const Bds5Response& response) {
    if (!m_running || m_pending != id) return;
    m_pending.reset();
    answered(response);
}

void Bds5Transfer::onFailed(quint64 id, const QString& reason) {
    if (!m_running || m_pending != id) return;
    m_pending.reset();
    lost(reason);
}

void Bds5Transfer::onRaw(const QByteArray& bytes) {
    if (!m_counting || !m_pending) return;
    const int before = m_counted;
    m_counted += int(bytes.count('\n'));
    if (m_counted > before && m_counted > 0) emit progress(m_countBase + m_counted, m_countTotal);
}

QString describeError(const Bds5ErrorLine& error) {
    QString text = QStringLiteral("ERR %1").arg(error.code);
    if (error.programLine > 0) text += QStringLiteral(" LINE %1").arg(error.programLine);
    if (!error.entry.isEmpty()) text += QStringLiteral(" '%1'").arg(error.entry);
    return text + QStringLiteral(" ") + error.message;
}

} // namespace serialport
