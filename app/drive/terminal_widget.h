// TerminalWidget: a serial terminal on the drive. Shows what the drive sends (it echoes what we type,
// so nothing is echoed locally) and turns key presses into the bytes a user's terminal would send.
// GUI thread only.
#pragma once

#include "command_history.h"

#include <QByteArray>
#include <QPlainTextEdit>
#include <QTextCursor>

namespace app {

class TerminalWidget final : public QPlainTextEdit {
    Q_OBJECT
public:
    explicit TerminalWidget(QWidget* parent = nullptr);

    // Renders bytes from the drive (Latin-1): CR LF and lone LF start a line, a lone CR returns to the
    // start of the line (later characters overwrite it), BS erases the character before the cursor,
    // BEL flashes the terminal, other control characters are dropped.
    void displayBytes(const QByteArray& bytes);
    // A line from the IDE itself (a link error, "connected to ..."), set apart from the drive's text.
    void displayNotice(const QString& message);
    // What the terminal shows, lines joined by '\n'.
    QString text() const { return toPlainText(); }
    // The lines typed here and sent with Enter (F3 recalls the newest, Up/Down browse them).
    const CommandHistory& history() const { return m_history; }
    // The part of the current line typed since the last Enter, as the drive has it (it echoes it).
    QString typedLine() const { return m_typed; }
    // Erases the half-typed line on the drive (backspaces), so a command from a menu starts on a clean line.
    void discardTypedLine();
    // Background and text colours (the theme), and the colour bells flash.
    void setColours(const QColor& background, const QColor& foreground);

    static constexpr int kMaxLines = 5000;

signals:
    // Bytes to send to the drive, as typed: printable characters, CR for Enter, BS, ^V.
    void bytesTyped(const QByteArray& bytes);
    // ^X (stop motion) and Esc (monitor): must reach the drive at once, ahead of anything queued.
    void urgentBytesTyped(const QByteArray& bytes);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

private:
    static QByteArray bytesForKey(const QKeyEvent* event);
    void writePrintable(const QString& run);
    void newLine();
    void eraseBack();
    void bell();
    void pasteToDrive();
    void send(const QByteArray& bytes);
    void replaceTypedLine(const QString& line);
    void showWriteCursor();

    QTextCursor m_cursor; // where the next byte from the drive goes; always in the last block
    CommandHistory m_history;
    QString m_typed; // the line being typed: what the drive has echoed since the last CR, Esc or ^X
    QColor m_background;
};

} // namespace app
