// LineLocator: matching drive lines to editor lines.
#include "line_locator.h"

namespace app {

QString LineLocator::normalized(const QString& line, bool keepIndent) {
    // A comment starts at ';' preceded by a blank (or at the start of the line), outside quotes.
    QString code;
    bool inString = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (c == QLatin1Char('"')) inString = !inString;
        if (!inString && c == QLatin1Char(';') && (i == 0 || line[i - 1].isSpace())) break;
        code += c;
    }
    qsizetype indent = 0;
    while (keepIndent && indent < code.size() && code[indent].isSpace()) ++indent;
    const QString body = code.simplified().toUpper();
    return body.isEmpty() ? body : code.left(indent) + body;
}

int LineLocator::find(const QStringList& lines, const QString& driveText, int after) {
    const int count = int(lines.size());
    if (count == 0) return -1;
    for (const bool keepIndent : {true, false}) {
        QString wanted = normalized(driveText, keepIndent);
        const bool whole = wanted.isEmpty(); // a comment line: compare it all
        if (whole) wanted = driveText.simplified().toUpper();
        if (wanted.isEmpty()) return -1;
        for (int step = 1; step <= count; ++step) {
            const int i = ((after + step) % count + count) % count;
            const QString candidate = whole ? lines[i].simplified().toUpper() : normalized(lines[i], keepIndent);
            if (candidate == wanted) return i;
        }
    }
    return -1;
}

int LineLocator::labelLine(const QStringList& lines, int label) {
    const QString wanted = QString::number(label) + QLatin1Char('$');
    for (int i = 0; i < lines.size(); ++i) {
        const QString code = normalized(lines[i]);
        if (code == wanted || code.startsWith(wanted + QLatin1Char(' '))) return i;
    }
    return -1;
}

} // namespace app
