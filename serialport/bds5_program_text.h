// Bds5ProgramText: an editor's program text made ready for >BDS — split into lines, optionally without
// comments (Motion Link's "transmitted without comments", L1157, L5473) — with the map between the drive's
// program line numbers (ERR 83 LINE n) and the editor's lines. Pure; no I/O.
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

namespace serialport {

class Bds5ProgramText {
public:
    // text: the editor's text (LF or CR LF line ends). With stripComments, comment-only and blank lines
    // are not sent and a trailing " ;comment" is cut off (quoted text is left alone).
    static Bds5ProgramText prepare(const QString& text, bool stripComments);

    // The lines to send, in order, one per l-> prompt.
    const QStringList& lines() const { return m_lines; }
    int lineCount() const { return int(m_lines.size()); }
    // 1-based drive line -> 1-based editor line; 0 if the drive has no such line from this text.
    int sourceLine(int driveLine) const;
    // 1-based editor line -> 1-based drive line; 0 if that editor line was not sent.
    int driveLine(int sourceLine) const;
    int charactersSent() const;                    // the characters the lines take, each with its CR
    int skippedLines() const { return m_skipped; } // comment and blank lines left out by stripping

    // ';' starts a comment at the start of a line or after a blank, outside quotes (L1355-1365).
    // The position of that ';', or -1.
    static int commentStart(const QString& line);
    // The line holds nothing but blanks and maybe a comment: Motion Link does not send it when stripping
    // (and "go to line" without counting comment lines skips it).
    static bool isCommentLine(const QString& line);

private:
    QStringList m_lines;
    QList<int> m_sourceLines; // per sent line, its 1-based editor line
    int m_skipped = 0;
};

} // namespace serialport
