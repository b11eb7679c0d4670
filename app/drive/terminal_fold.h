// TerminalFold: the byte filter behind TerminalWidget::beginFold. It passes the drive's bytes through up to
// the end of the first line (the command's echo); after that it holds each line until its line end and
// leaves out the lines `hide` accepts, counting them. An unfinished last line (the prompt that ends the
// answer) stays held until the fold ends. Pure logic, no widgets.
#pragma once

#include <QByteArray>
#include <QString>

#include <functional>

namespace app {

class TerminalFold {
public:
    // A complete line without its CR LF; true to leave it out of the terminal.
    using Hide = std::function<bool(const QString& line)>;

    explicit TerminalFold(Hide hide);

    // Of bytes just received (Latin-1, any chunking), the ones to show now.
    QByteArray filter(const QByteArray& bytes);
    // Ends the fold: the bytes still held (the unfinished last line), to be shown after the summary.
    QByteArray takeHeld();
    int hiddenLines() const { return m_hidden; }

private:
    Hide m_hide;
    bool m_pastEcho = false; // the echo's line end went by: the answer's lines follow
    QByteArray m_line;       // the answer's line being received, not shown yet
    int m_hidden = 0;
};

} // namespace app
