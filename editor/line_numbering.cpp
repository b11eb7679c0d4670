// Editor line <-> drive line mapping, with and without comment lines.
#include "line_numbering.h"

#include <QRegularExpression>

namespace editor {

bool isCommentLine(QStringView line) {
    for (const QChar c : line) {
        if (c == QLatin1Char(' ') || c == QLatin1Char('\t')) continue;
        return c == QLatin1Char(';');
    }
    return true; // blank
}

QStringList splitLines(const QString& text) {
    static const QRegularExpression kBreak(QStringLiteral("\r\n|\n|\r"));
    QStringList lines = text.split(kBreak);
    if (lines.size() > 1 && lines.last().isEmpty()) lines.removeLast();
    return lines;
}

int editorLineForDriveLine(const QStringList& lines, int driveLine, LineCounting counting) {
    if (driveLine < 1) return -1;
    if (counting == LineCounting::AllLines) return driveLine <= lines.size() ? driveLine - 1 : -1;
    int counted = 0;
    for (int i = 0; i < lines.size(); ++i) {
        if (isCommentLine(lines[i])) continue;
        if (++counted == driveLine) return i;
    }
    return -1;
}

int driveLineForEditorLine(const QStringList& lines, int editorLine, LineCounting counting) {
    if (editorLine < 0 || editorLine >= lines.size()) return -1;
    if (counting == LineCounting::AllLines) return editorLine + 1;
    int counted = 0;
    for (int i = 0; i < lines.size(); ++i) {
        if (isCommentLine(lines[i])) continue;
        ++counted;
        if (i >= editorLine) return counted;
    }
    return -1;
}

int driveLineCount(const QStringList& lines, LineCounting counting) {
    if (counting == LineCounting::AllLines) return int(lines.size());
    int counted = 0;
    for (const QString& line : lines)
        if (!isCommentLine(line)) ++counted;
    return counted;
}

} // namespace editor
