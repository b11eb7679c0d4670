// A one-line scanner over the SC750 catalog's names.
#include "servobasic_line_styler.h"

#include "drive_core/catalog/sc750_catalog.h"

#include <QHash>

namespace editor {

namespace catalog = drive_core::catalog::sc750;

namespace {

// Reserved words the catalog lists under no statement of their own (parts of IF, FOR, DIM, WHEN...).
constexpr const char* kReserved[] = {"THEN",    "ELSE",  "ELSEIF", "END",    "TO",     "STEP",      "NEXT",    "AS",
                                     "INTEGER", "FLOAT", "SINGLE", "DOUBLE", "STRING", "AND",       "OR",      "NOT",
                                     "XOR",     "MOD",   "PARAMS", "START",  "SUB",    "INTERRUPT", "RESTART", "LOOP",
                                     "WHILE",   "WEND",  "UNTIL",  "DO",     "CALL",   "GOSUB",     "GOTO",    "RETURN",
                                     "REM",     "DIM",   "ON",     "OFF",    "WHEN",   "SELECT",    "CASE",    "IS",
                                     "EXIT",    "STOP",  "PRINT",  "INPUT",  "IF",     "FOR"};

const QHash<QByteArray, ServoBasicStyle>& words() {
    static const QHash<QByteArray, ServoBasicStyle> table = [] {
        QHash<QByteArray, ServoBasicStyle> t;
        for (const catalog::VariableInfo& v : catalog::variables())
            t.insert(QByteArray(v.name.data(), qsizetype(v.name.size())), BasicVariable);
        for (const catalog::FunctionInfo& f : catalog::functions())
            t.insert(QByteArray(f.name.data(), qsizetype(f.name.size())), BasicFunction);
        for (const catalog::StatementInfo& s : catalog::statements())
            for (const QByteArray& part : QByteArray(s.name.data(), qsizetype(s.name.size())).split(' '))
                if (!part.isEmpty()) t.insert(part, BasicKeyword);
        for (const char* word : kReserved) t.insert(word, BasicKeyword);
        return t;
    }();
    return table;
}

bool isWordStart(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
}
bool isWordChar(char c) {
    return isWordStart(c) || (c >= '0' && c <= '9') || c == '.' || c == '$';
}

} // namespace

ServoBasicStyle servoBasicWordStyle(const QByteArray& word) {
    return words().value(word.toUpper(), BasicDefault);
}

QByteArray styleServoBasicLine(const QByteArray& line) {
    QByteArray styles(line.size(), BasicDefault);
    qsizetype k = 0;
    while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
    const qsizetype first = k;
    while (k < line.size()) {
        const char c = line[k];
        const auto fill = [&](qsizetype from, qsizetype to, char style) {
            for (qsizetype i = from; i < to; ++i) styles[i] = style;
        };
        // ' starts a comment; so do the typographic quotes the manual's listings carry (UTF-8 E2 80 98/99).
        if (c == '\'' || (c == '\xe2' && line.mid(k, 2) == "\xe2\x80")) {
            fill(k, line.size(), BasicComment);
            break;
        }
        if (c == '"') {
            qsizetype end = line.indexOf('"', k + 1);
            end = end < 0 ? line.size() : end + 1;
            fill(k, end, BasicString);
            k = end;
            continue;
        }
        if ((c >= '0' && c <= '9') || (c == '.' && k + 1 < line.size() && line[k + 1] >= '0' && line[k + 1] <= '9')) {
            qsizetype end = k;
            while (end < line.size() &&
                   ((line[end] >= '0' && line[end] <= '9') || line[end] == '.' || line[end] == 'E' || line[end] == 'e'))
                ++end;
            fill(k, end, BasicNumber);
            k = end;
            continue;
        }
        if (isWordStart(c)) {
            qsizetype end = k;
            while (end < line.size() && isWordChar(line[end])) ++end;
            const QByteArray word = line.mid(k, end - k);
            if (word.compare("REM", Qt::CaseInsensitive) == 0) {
                fill(k, line.size(), BasicComment);
                break;
            }
            ServoBasicStyle style = servoBasicWordStyle(word);
            if (k == first && end < line.size() && line[end] == ':' && style == BasicDefault) {
                style = BasicLabel;
                ++end;
            }
            fill(k, end, style);
            k = end;
            continue;
        }
        ++k;
    }
    return styles;
}

} // namespace editor
