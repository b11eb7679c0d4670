// Bds5BusScan: call each ID, credit each prompt to the ID it carries.
#include "bds5_bus_scan.h"

#include "link.h"

#include <QRegularExpression>

#include <algorithm>

namespace serialport {

namespace {
// A multidrop prompt at the start of a line: the ID, the mode character, '>' (Table 4.17; "A->" interactive).
const QRegularExpression kPrompt(QStringLiteral("\\r\\n([0-9A-Z])([-=setlifc])>"));

QString modeName(QChar c) {
    switch (c.unicode()) {
    case '-': return QStringLiteral("interactive");
    case '=': return QStringLiteral("monitor");
    case 's': return QStringLiteral("single step");
    case 't': return QStringLiteral("trace");
    case 'l': return QStringLiteral("program upload");
    case 'e': return QStringLiteral("editor");
    case 'i': return QStringLiteral("editor input");
    case 'f': return QStringLiteral("editor find");
    case 'c': return QStringLiteral("editor change");
    }
    return QString(c);
}
} // namespace

QString Bds5BusScan::allIds() {
    return QStringLiteral("0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ");
}

Bds5BusScan::Bds5BusScan(Link& link, QString ids, int waitMs, QObject* parent)
    : QObject(parent), m_link(link), m_ids(std::move(ids)), m_waitMs(waitMs), m_wait(link) {
    connect(&m_link, &Link::bytesReceived, this, &Bds5BusScan::onBytes);
    connect(&m_wait, &DriveTimeout::timeout, this, &Bds5BusScan::callNext);
}

void Bds5BusScan::start() {
    m_next = 0;
    m_axes.clear();
    m_received.clear();
    m_done = false;
    callNext();
}

void Bds5BusScan::callNext() {
    if (m_done) return;
    if (m_next >= m_ids.size()) {
        m_done = true;
        m_wait.stop();
        m_link.write("\\\r"); // '\' and a character that is no ID: every axis asleep again
        std::sort(m_axes.begin(), m_axes.end(), [](const Axis& a, const Axis& b) {
            return allIds().indexOf(a.id) < allIds().indexOf(b.id);
        });
        emit finished(m_axes);
        return;
    }
    emit progress(m_next, int(m_ids.size()));
    m_link.write(QByteArray("\\") + m_ids.at(m_next++).toLatin1());
    m_wait.start(m_waitMs);
}

void Bds5BusScan::onBytes(const QByteArray& bytes) {
    if (m_done) return;
    m_received += bytes;
    bool answered = false;
    for (auto it = kPrompt.globalMatch(QString::fromLatin1(m_received)); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const QChar id = m.captured(1).at(0);
        answered = answered || (m_next > 0 && id == m_ids.at(m_next - 1));
        if (std::none_of(m_axes.begin(), m_axes.end(), [id](const Axis& a) { return a.id == id; }))
            m_axes.append({id, m.captured(1) + m.captured(2) + QLatin1Char('>'), modeName(m.captured(2).at(0))});
    }
    const qsizetype lastLine = m_received.lastIndexOf("\r\n");
    if (lastLine > 0) m_received.remove(0, lastLine); // keep a prompt that may be arriving in pieces
    if (answered) { // the axis called is there: on to the next at once
        m_wait.stop();
        callNext();
    }
}

} // namespace serialport
