// CaptureLog: recording, the .CAP file, the transcript.
#include "capture_log.h"

#include <QFile>
#include <QSaveFile>

namespace app {

namespace {
QString escaped(const QByteArray& bytes) {
    QString text;
    for (const char byte : bytes) {
        const auto c = uchar(byte);
        switch (c) {
        case '\r': text += QStringLiteral("<CR>"); break;
        case '\n': text += QStringLiteral("<LF>"); break;
        case 0x07: text += QStringLiteral("<BEL>"); break;
        case 0x08: text += QStringLiteral("<BS>"); break;
        case 0x16: text += QStringLiteral("<^V>"); break;
        case 0x18: text += QStringLiteral("<^X>"); break;
        case 0x1b: text += QStringLiteral("<ESC>"); break;
        default:
            if (c < 0x20 || c == 0x7f) text += QStringLiteral("<%1h>").arg(c, 2, 16, QLatin1Char('0')).toUpper();
            else text += QChar(char16_t(c));
        }
    }
    return text;
}
} // namespace

CaptureLog::CaptureLog(QObject* parent) : QObject(parent) {}

void CaptureLog::start() {
    clear();
    m_clock.start();
    m_capturing = true;
    emit capturingChanged(true);
}

void CaptureLog::stop() {
    if (!m_capturing) return;
    m_capturing = false;
    emit capturingChanged(false);
}

void CaptureLog::clear() {
    m_entries.clear();
    m_received = m_sent = 0;
    if (m_capturing) m_clock.restart();
    emit changed();
}

void CaptureLog::add(Direction direction, const QByteArray& bytes) {
    if (!m_capturing || bytes.isEmpty()) return;
    const qint64 now = m_clock.elapsed();
    (direction == Direction::Received ? m_received : m_sent) += bytes.size();
    // Split at line ends so each drive line is an entry of its own.
    qsizetype from = 0;
    while (from < bytes.size()) {
        const qsizetype lf = bytes.indexOf('\n', from);
        const qsizetype end = lf < 0 ? bytes.size() : lf + 1;
        const QByteArray piece = bytes.mid(from, end - from);
        Entry* last = m_entries.empty() ? nullptr : &m_entries.back();
        if (last && last->direction == direction && !last->bytes.endsWith('\n') &&
            now - last->atMs < kQuietMs)
            last->bytes += piece;
        else
            m_entries.push_back({now, direction, piece});
        from = end;
    }
    emit changed();
}

QByteArray CaptureLog::capBytes() const {
    QByteArray bytes;
    bytes.reserve(m_received);
    for (const Entry& e : m_entries)
        if (e.direction == Direction::Received) bytes += e.bytes;
    return bytes;
}

QString CaptureLog::transcript() const {
    QString text;
    for (const Entry& e : m_entries) {
        text += QStringLiteral("%1 s  %2  %3\n")
                    .arg(double(e.atMs) / 1000.0, 9, 'f', 3)
                    .arg(e.direction == Direction::Received ? QStringLiteral("<") : QStringLiteral(">"))
                    .arg(escaped(e.bytes));
    }
    return text;
}

QString CaptureLog::saveCap(const QString& path) const {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return tr("Cannot write %1: %2").arg(path, file.errorString());
    file.write(capBytes());
    if (!file.commit()) return tr("Cannot write %1: %2").arg(path, file.errorString());
    return {};
}

QString CaptureLog::loadCap(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return tr("Cannot open %1: %2").arg(path, file.errorString());
    const QByteArray bytes = file.readAll();
    stop();
    m_entries.clear();
    m_sent = 0;
    m_received = bytes.size();
    if (!bytes.isEmpty()) m_entries.push_back({0, Direction::Received, bytes});
    emit changed();
    return {};
}

} // namespace app
