// The PMC-960 program upload.
#include "pmc960_upload.h"

namespace serialport {

Pmc960Upload::Pmc960Upload(Pmc960Session& session, QObject* parent) : QObject(parent), m_session(session) {
    connect(&m_session, &Pmc960Session::finished, this, [this](quint64 id, const Pmc960Response& response) {
        if (id != m_waiting) return;
        m_waiting = 0;
        if (response.error != 0) {
            emit done(false, {}, response.errorText);
            return;
        }
        emit done(true, linesFromListing(response.text), {});
    });
    connect(&m_session, &Pmc960Session::failed, this, [this](quint64 id, const QString& reason) {
        if (id != m_waiting) return;
        m_waiting = 0;
        emit done(false, {}, reason);
    });
}

void Pmc960Upload::start(int timeoutMs) {
    m_waiting = m_session.send("P!", timeoutMs);
}

QStringList Pmc960Upload::linesFromListing(const QByteArray& text) {
    QStringList lines;
    const QList<QByteArray> parts = text.split('\n');
    for (QByteArray part : parts) {
        if (part.endsWith('\r')) part.chop(1);
        lines << QString::fromLatin1(part);
    }
    if (!lines.isEmpty() && lines.first().isEmpty()) lines.removeFirst(); // the CR LF before the first line
    return lines;
}

} // namespace serialport
