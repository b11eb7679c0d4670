// Bds5VariableFile: the .VAR reader and writer (format documented in the header).
#include "bds5_variable_file.h"

#include "bds5_program_text.h"

#include <QObject>
#include <QRegularExpression>

namespace serialport {

Bds5VariableFile Bds5VariableFile::parse(const QString& text) {
    // NAME: a letter then letters/digits (VMAX, X12, XS3); value: one entry without blanks (a number, 0FFH,
    // a constant such as ON). Expressions have no blanks either (Table 3.3), so one entry covers them.
    // Blanks are spaces and tabs only, as for comments (Bds5ProgramText::commentStart): with any other
    // white space as a separator, "RE\f;;" would read as RE = ";;" here and as a comment once written
    // back (found by host_parsers_fuzz). For the same reason a value does not begin with ';'.
    static const QRegularExpression kAssignment(
        QStringLiteral("^[ \\t]*([A-Za-z][A-Za-z0-9]*)(?:[ \\t]*=[ \\t]*|[ \\t]+)([^ \\t=;][^ \\t=]*)[ \\t]*$"));
    static const QRegularExpression kClearX(QStringLiteral("^\\s*CLEARX\\s*$"),
                                            QRegularExpression::CaseInsensitiveOption);
    Bds5VariableFile out;
    // A CR ends a line for the drive, as LF does (CRLF counts once).
    static const QRegularExpression kLineEnd(QStringLiteral("\r\n|\r|\n"));
    const QStringList lines = text.split(kLineEnd);
    for (int i = 0; i < lines.size(); ++i) {
        const QString& line = lines[i];
        if (Bds5ProgramText::isCommentLine(line)) continue;
        const int comment = Bds5ProgramText::commentStart(line);
        const QString code = comment < 0 ? line : line.left(comment);
        if (kClearX.match(code).hasMatch()) {
            out.m_assignments.append({i + 1, QStringLiteral("CLEARX"), QString()});
            continue;
        }
        const auto match = kAssignment.match(code);
        if (!match.hasMatch()) {
            out.m_problems.append({i + 1, line, QObject::tr("not an assignment (NAME value)")});
            continue;
        }
        out.m_assignments.append({i + 1, match.captured(1).toUpper(), match.captured(2)});
    }
    return out;
}

Bds5VariableFile Bds5VariableFile::fromDump(const QStringList& dumpLines) {
    return parse(dumpLines.join(QLatin1Char('\n')));
}

QString Bds5VariableFile::toText(const QStringList& headerComments) const {
    QString text;
    for (const QString& comment : headerComments)
        text += QStringLiteral("; ") + comment + QLatin1Char('\n');
    for (const Bds5Assignment& a : m_assignments)
        text += a.instruction() + QLatin1Char('\n');
    return text;
}

QString Bds5VariableFile::valueOf(const QString& name) const {
    const QString upper = name.toUpper();
    for (auto it = m_assignments.crbegin(); it != m_assignments.crend(); ++it)
        if (it->name == upper) return it->value;
    return {};
}

} // namespace serialport
