// Line numbers as the drive sees them. Motion Link can transmit a program without its comments, so a
// drive's "LINE n" may count only the lines that carry code (manual L1157). These functions map between
// editor lines and drive lines in both counting modes. Pure; any thread.
#pragma once

#include <QString>
#include <QStringList>
#include <QStringView>

namespace editor {

// How drive line numbers are counted.
enum class LineCounting {
    AllLines,        // every editor line counts (the program was sent with its comments)
    WithoutComments, // comment-only and blank lines are skipped (the program was sent without comments)
};

// True for a line that is dropped when a program is sent without comments: blank, or nothing but a
// comment (';' as the first non-blank character).
// chosen: blank lines go with comment lines — they carry no code, and a drive program has none.
bool isCommentLine(QStringView line);

// Splits editor text into lines ("\r\n", "\n" or "\r"); a final line break does not start a new line.
QStringList splitLines(const QString& text);

// The 0-based editor line of 1-based drive line driveLine, or -1 when there is no such line.
int editorLineForDriveLine(const QStringList& lines, int driveLine, LineCounting counting);
// The 1-based drive line of 0-based editorLine; for a comment line under WithoutComments, the drive line
// of the next code line (where the drive would be), or -1 when none follows.
int driveLineForEditorLine(const QStringList& lines, int editorLine, LineCounting counting);
// How many lines the drive would receive.
int driveLineCount(const QStringList& lines, LineCounting counting);

} // namespace editor
