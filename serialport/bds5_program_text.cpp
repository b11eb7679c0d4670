// Bds5ProgramText: line splitting, comment stripping and the drive-line map.
#include "bds5_program_text.h"

namespace serialport {

namespace {
bool isBlank(QChar c) {
    return c == QLatin1Char(' ') || c == QLatin1Char('\t');
}
} // namespace

int Bds5ProgramText::commentStart(const QString& line) {
    bool quoted = false;
    for (int i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (c == QLatin1Char('"'))
            quoted = !quoted;
        else if (c == QLatin1Char(';') && !quoted && (i == 0 || isBlank(line[i - 1])))
            return i;
    }
    return -1;
}

bool Bds5ProgramText::isCommentLine(const QString& line) {
    const int comment = commentStart(line);
    const QString code = comment < 0 ? line : line.left(comment);
    return code.trimmed().isEmpty();
}

Bds5ProgramText Bds5ProgramText::prepare(const QString& text, bool stripComments) {
    Bds5ProgramText out;
    QStringList lines = text.split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.last().isEmpty()) lines.removeLast(); // the text's final line end
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
        // chosen: a tab is sent as a space. The drive ignores control characters (its UART drops them), so
        // a tab would vanish and join the words either side; to the drive's lexer both are blanks.
        line.replace(QLatin1Char('\t'), QLatin1Char(' '));
        if (stripComments) {
            if (isCommentLine(line)) {
                ++out.m_skipped;
                continue;
            }
            if (const int comment = commentStart(line); comment >= 0) line.truncate(comment);
            while (!line.isEmpty() && isBlank(line.back()))
                line.chop(1);
        }
        out.m_lines.append(line);
        out.m_sourceLines.append(i + 1);
    }
    return out;
}

int Bds5ProgramText::sourceLine(int driveLine) const {
    if (driveLine < 1 || driveLine > m_sourceLines.size()) return 0;
    return m_sourceLines[driveLine - 1];
}

int Bds5ProgramText::driveLine(int sourceLine) const {
    const qsizetype at = m_sourceLines.indexOf(sourceLine);
    return at < 0 ? 0 : int(at) + 1;
}

int Bds5ProgramText::charactersSent() const {
    int total = 0;
    for (const QString& line : m_lines)
        total += int(line.size()) + 1;
    return total;
}

} // namespace serialport
