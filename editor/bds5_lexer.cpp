// BDS5 lexer rules (seed-bds5 §4.1, §4.5): `;` starts a comment at the start of a line or after white
// space; strings are double-quoted; a label is `<number>$` or a dedicated name like `POWER-UP$` first on
// its line; a number is a word that starts with a digit (decimal, or hex ending in H).
#include "bds5_lexer.h"

#include <Qsci/qsciscintilla.h>

#include <QColor>

namespace editor {

namespace {
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}
bool isWordChar(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
} // namespace

Bds5Lexer::Bds5Lexer(QObject* parent) : QsciLexerCustom(parent) {}

QString Bds5Lexer::description(int style) const {
    switch (style) {
    case Default:
        return tr("Default");
    case Comment:
        return tr("Comment");
    case String:
        return tr("String");
    case Label:
        return tr("Label");
    case Number:
        return tr("Number");
    default:
        return {};
    }
}

QColor Bds5Lexer::defaultColor(int style) const {
    switch (style) {
    case Comment:
        return QColor(0x5f, 0x80, 0x5f);
    case String:
        return QColor(0xa3, 0x3b, 0x14);
    case Label:
        return QColor(0x6a, 0x2c, 0xa8);
    case Number:
        return QColor(0x0b, 0x6e, 0x8a);
    default:
        return QColor(0x1e, 0x1e, 0x1e);
    }
}

QByteArray Bds5Lexer::styleLine(const QByteArray& line) {
    const qsizetype n = line.size();
    QByteArray styles(n, char(Default));
    qsizetype i = 0;
    while (i < n && isSpace(line[i]))
        ++i;

    // A label first on the line: digits or a name (letters, '-') right before '$'.
    qsizetype j = i;
    while (j < n && (isWordChar(line[j]) || line[j] == '-'))
        ++j;
    if (j > i && j < n && line[j] == '$') {
        for (qsizetype k = i; k <= j; ++k)
            styles[k] = char(Label);
        i = j + 1;
    }

    while (i < n) {
        const char c = line[i];
        if (c == ';' && (i == 0 || isSpace(line[i - 1]))) {
            for (qsizetype k = i; k < n; ++k)
                styles[k] = char(Comment);
            break;
        }
        if (c == '"') {
            qsizetype k = i + 1;
            while (k < n && line[k] != '"' && line[k] != '\r' && line[k] != '\n')
                ++k;
            const qsizetype endQuote = (k < n && line[k] == '"') ? k + 1 : k;
            for (qsizetype m = i; m < endQuote; ++m)
                styles[m] = char(String);
            i = endQuote;
            continue;
        }
        if (isWordChar(c)) {
            qsizetype k = i;
            while (k < n && isWordChar(line[k]))
                ++k;
            if (isDigit(c))
                for (qsizetype m = i; m < k; ++m)
                    styles[m] = char(Number);
            i = k;
            continue;
        }
        ++i;
    }
    return styles;
}

void Bds5Lexer::styleText(int start, int end) {
    QsciScintilla* ed = editor();
    if (!ed) return;
    // Restyle whole lines: the rules look back to the start of the line.
    const int firstLine = int(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, start));
    const int lastLine = int(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, end));
    for (int line = firstLine; line <= lastLine; ++line) {
        const long lineStart = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line);
        const long lineEnd = ed->SendScintilla(QsciScintilla::SCI_GETLINEENDPOSITION, line);
        if (lineEnd <= lineStart) continue;
        QByteArray bytes(lineEnd - lineStart + 1, '\0');
        ed->SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, lineStart, lineEnd, bytes.data());
        bytes.chop(1); // the terminating NUL
        const QByteArray styles = styleLine(bytes);
        startStyling(int(lineStart));
        qsizetype runStart = 0;
        for (qsizetype k = 1; k <= styles.size(); ++k) {
            if (k == styles.size() || styles[k] != styles[runStart]) {
                setStyling(int(k - runStart), styles[runStart]);
                runStart = k;
            }
        }
    }
}

} // namespace editor
