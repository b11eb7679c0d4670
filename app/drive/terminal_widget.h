// TerminalWidget: a serial terminal on the drive. Shows what the drive sends (it echoes what we type,
// so nothing is echoed locally) and turns key presses into the bytes a user's terminal would send.
// GUI thread only.
#pragma once

#include "command_history.h"
#include "terminal_fold.h"

#include <QByteArray>
#include <QPlainTextEdit>
#include <QTextCursor>
#include <QTimer>

#include <optional>

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
    // Folds a long answer (a PLAY listing of hundreds of samples) into one line. After the end of the next
    // line (the command's echo), the lines from the drive that hide accepts are left out and an unfinished
    // last line (the prompt) waits; endFold() shows summary in their place, then what waited. Other lines
    // show as usual. Only the view is folded: whoever reads the drive's bytes gets them all. A new fold ends
    // the one before; endFold() with another fold's number does nothing.
    int beginFold(TerminalFold::Hide hide);
    void endFold(int fold, const QString& summary);
    bool isFolding() const { return m_fold.has_value(); }
    // Whether new output scrolls into view: true until the user scrolls up, true again once they scroll
    // back to the bottom (or type). Hiding, showing and resizing the terminal do not change it.
    bool isFollowingOutput() const { return m_following; }
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
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    static QByteArray bytesForKey(const QKeyEvent* event);
    void render(const QByteArray& bytes);
    void writeOwnLine(const QString& text, const QTextCharFormat& format);
    void followEnd();
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
    std::optional<TerminalFold> m_fold;
    int m_foldNumber = 0;    // of the last beginFold()
    bool m_following = true; // changed only by the user's own scrolling, never by a layout change
    QTimer m_followLater;    // once a show or resize has settled, scroll to the end again
};

} // namespace app
