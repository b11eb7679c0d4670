// CommandHistory: the lines the user typed in the terminal, newest last, for F3 (last command) and Up/Down.
// Kept in QSettings ("terminal/history") so it survives a restart; capped at kCapacity lines.
#pragma once

#include <QString>
#include <QStringList>

namespace app {

class CommandHistory {
public:
    static constexpr int kCapacity = 200; // chosen: Motion Link kept only the last command (F3)

    // Loads the history saved by earlier sessions.
    CommandHistory();

    // A line the user sent with Enter. Blank lines and a repeat of the newest line are not added.
    void add(const QString& line);
    QString last() const { return m_lines.isEmpty() ? QString() : m_lines.last(); }
    const QStringList& lines() const { return m_lines; }

    // Browsing: previous() walks back from the newest line, next() forward; next() past the newest line
    // gives the line the user was typing before browsing. add() and resetBrowsing() end the walk.
    QString previous(const QString& typing);
    QString next(const QString& typing);
    void resetBrowsing() { m_browse = -1; }

private:
    void save() const;

    QStringList m_lines;
    int m_browse = -1; // index into m_lines while browsing, -1 when not
    QString m_typing;  // what was typed when browsing began
};

} // namespace app
