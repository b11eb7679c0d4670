// CommandHistory: persistence and browsing.
#include "command_history.h"

#include <QSettings>

namespace app {

namespace {
const QString kKey = QStringLiteral("terminal/history");
}

CommandHistory::CommandHistory() {
    m_lines = QSettings().value(kKey).toStringList();
    while (m_lines.size() > kCapacity) m_lines.removeFirst();
}

void CommandHistory::add(const QString& line) {
    m_browse = -1;
    if (line.trimmed().isEmpty() || line == last()) return;
    m_lines.append(line);
    while (m_lines.size() > kCapacity) m_lines.removeFirst();
    save();
}

QString CommandHistory::previous(const QString& typing) {
    if (m_lines.isEmpty()) return typing;
    if (m_browse < 0) {
        m_typing = typing;
        m_browse = int(m_lines.size());
    }
    if (m_browse > 0) --m_browse;
    return m_lines.at(m_browse);
}

QString CommandHistory::next(const QString& typing) {
    if (m_browse < 0) return typing;
    if (++m_browse >= m_lines.size()) {
        m_browse = -1;
        return m_typing;
    }
    return m_lines.at(m_browse);
}

void CommandHistory::save() const {
    QSettings().setValue(kKey, m_lines);
}

} // namespace app
