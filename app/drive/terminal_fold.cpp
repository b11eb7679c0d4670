// TerminalFold: line-by-line filtering of one answer.
#include "terminal_fold.h"

#include <utility>

namespace app {

TerminalFold::TerminalFold(Hide hide) : m_hide(std::move(hide)) {}

QByteArray TerminalFold::filter(const QByteArray& bytes) {
    QByteArray shown;
    for (const char byte : bytes) {
        if (!m_pastEcho) {
            shown += byte;
            m_pastEcho = byte == '\n';
            continue;
        }
        m_line += byte;
        if (byte != '\n') continue;
        QString line = QString::fromLatin1(m_line);
        line.remove(QLatin1Char('\r'));
        line.chop(1); // the LF
        if (m_hide && m_hide(line))
            ++m_hidden;
        else
            shown += m_line; // an ERR line in the answer, say: the user must see it
        m_line.clear();
    }
    return shown;
}

QByteArray TerminalFold::takeHeld() {
    return std::exchange(m_line, {});
}

} // namespace app
