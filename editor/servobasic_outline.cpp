// ServoBASIC outline: each line's first name, after taking off its comment (' or REM, outside a string).
#include "servobasic_outline.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "drive_core/sc750/sc750_parser.h"

#include <QObject>
#include <QStringList>

namespace editor {

namespace {

namespace cat = drive_core::catalog::sc750;

bool isNameStart(QChar c) {
    return c.isLetter() && c.unicode() < 0x80;
}
bool isNameChar(QChar c) {
    return c.unicode() < 0x80 && (c.isLetterOrNumber() || c == QLatin1Char('_') || c == QLatin1Char('.'));
}

// The code of a line and its comment: ' (or the curly quotes a pasted manual line has) outside a string.
std::pair<QString, QString> splitComment(const QString& line) {
    bool inString = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line.at(i);
        if (c == QLatin1Char('"')) inString = !inString;
        else if (!inString && (c == QLatin1Char('\'') || c == QChar(0x2018) || c == QChar(0x2019)))
            return {line.left(i), line.mid(i + 1).trimmed()};
    }
    return {line, QString()};
}

// The name at from (after blanks), and where it ends; empty when none starts there.
QString nameAt(const QString& code, qsizetype& from) {
    while (from < code.size() && code.at(from).isSpace()) ++from;
    if (from >= code.size() || !isNameStart(code.at(from))) return {};
    const qsizetype start = from;
    while (from < code.size() && isNameChar(code.at(from))) ++from;
    if (from < code.size() && code.at(from) == QLatin1Char('$')) ++from;
    return code.mid(start, from - start);
}

bool reserved(const QString& name) {
    const std::string upper = name.toUpper().toStdString();
    return drive_core::sc750::Parser::isKeyword(upper) || cat::findVariable(upper) != nullptr;
}

} // namespace

Outline servoBasicOutline(const QString& programText) {
    Outline out;
    const QStringList lines = programLines(programText);
    for (qsizetype n = 0; n < lines.size(); ++n) {
        auto [code, comment] = splitComment(lines[n]);
        qsizetype at = 0;
        const QString first = nameAt(code, at);
        if (first.isEmpty()) continue;
        const QString word = first.toUpper();
        OutlineEntry entry;
        entry.line = int(n);
        if (word == QLatin1String("REM")) continue;
        if (word == QLatin1String("SUB") || word == QLatin1String("INTERRUPT")) {
            entry.name = nameAt(code, at);
            if (entry.name.isEmpty()) continue;
            if (word == QLatin1String("SUB")) {
                entry.kind = OutlineEntry::Kind::Task;
                entry.detail = QObject::tr("subroutine: CALL %1").arg(entry.name);
            } else {
                entry.kind = OutlineEntry::Kind::Handler;
                const int source = cat::interruptIndex(entry.name.toUpper().toStdString());
                if (source < 0) {
                    entry.detail = QObject::tr("interrupt routine: no such source");
                } else {
                    const std::string_view condition = cat::interruptSources()[std::size_t(source)].condition;
                    entry.detail = QObject::tr("runs when %1")
                                       .arg(QString::fromUtf8(condition.data(), qsizetype(condition.size())));
                }
            }
        } else {
            while (at < code.size() && code.at(at).isSpace()) ++at;
            if (at >= code.size() || code.at(at) != QLatin1Char(':') || reserved(first)) continue;
            entry.kind = OutlineEntry::Kind::Label;
            entry.name = first;
        }
        if (!comment.isEmpty()) entry.detail = comment;
        out.push_back(std::move(entry));
    }
    return out;
}

} // namespace editor
