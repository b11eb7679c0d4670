// ErrorStreamScanner: bell-led lines in, error lines out.
#include "error_stream_scanner.h"

#include <QStringList>

namespace app {

namespace {
constexpr char kBell = '\a';
constexpr int kMaxLine = 256; // a line this long without CR LF is not an error message
} // namespace

QList<serialport::Bds5ErrorLine> ErrorStreamScanner::feed(const QByteArray& bytes) {
    QList<serialport::Bds5ErrorLine> found;
    for (const char c : bytes) {
        if (c == '\r' || c == '\n') {
            // The bell opens the message; a prompt may stand before it on the same line (-->\aERR ...).
            if (const qsizetype bell = m_line.lastIndexOf(kBell); bell >= 0)
                if (const auto error = serialport::parseErrorLine(QString::fromLatin1(m_line.mid(bell))))
                    found.append(*error);
            m_line.clear();
        } else if (m_line.size() < kMaxLine) {
            m_line.append(c);
        }
    }
    return found;
}

QList<serialport::Bds5ErrorLine> ErrorStreamScanner::parseHistory(const QString& text) {
    QList<serialport::Bds5ErrorLine> rows;
    for (const QString& line : text.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QString trimmed = line.trimmed();
        if (const auto error = serialport::parseErrorLine(trimmed)) rows.append(*error);
    }
    return rows;
}

} // namespace app
