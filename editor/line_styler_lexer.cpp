// LineStylerLexer: whole-line styling in runs, fold levels and line state, and the style table's palette.
#include "line_styler_lexer.h"

#include <Qsci/qsciscintilla.h>

#include <QColor>

namespace editor {

namespace {
// The papers every language shares: GitHub-like white, VS Code Dark+-like #1e1e1e, and their error tints.
constexpr QRgb kLightPaper = 0xffffff;
constexpr QRgb kDarkPaper = 0x1e1e1e;
constexpr QRgb kLightErrorPaper = 0xffebe9;
constexpr QRgb kDarkErrorPaper = 0x4b1818;
} // namespace

LineStylerLexer::LineStylerLexer(std::span<const LexerStyle> styles, Theme theme, QObject* parent)
    : QsciLexerCustom(parent), m_styles(styles), m_theme(theme) {}

void LineStylerLexer::setTheme(Theme theme) {
    m_theme = theme;
    if (m_base != QFont()) applyStyles(m_base);
}

void LineStylerLexer::applyStyles(const QFont& base) {
    m_base = base;
    setDefaultFont(base);
    setDefaultColor(foreground());
    setDefaultPaper(paper());
    for (int style = 0; style < int(m_styles.size()); ++style) {
        QFont font = base;
        font.setBold(m_styles[std::size_t(style)].bold);
        font.setItalic(m_styles[std::size_t(style)].italic);
        setFont(font, style);
        setColor(defaultColor(style), style);
        setPaper(defaultPaper(style), style);
    }
}

QColor LineStylerLexer::paper() const {
    return QColor::fromRgb(m_theme == Theme::Dark ? kDarkPaper : kLightPaper);
}

QColor LineStylerLexer::foreground() const {
    return defaultColor(0);
}

QString LineStylerLexer::description(int style) const {
    // QScintilla counts a language's styles by their descriptions: none past the table.
    if (style < 0 || style >= int(m_styles.size())) return {};
    return tr(m_styles[std::size_t(style)].description);
}

QColor LineStylerLexer::defaultColor(int style) const {
    const LexerStyle& s = m_styles[style >= 0 && style < int(m_styles.size()) ? std::size_t(style) : 0];
    return QColor::fromRgb(m_theme == Theme::Dark ? s.darkInk : s.lightInk);
}

QColor LineStylerLexer::defaultPaper(int style) const {
    const bool error = style >= 0 && style < int(m_styles.size()) && m_styles[std::size_t(style)].error;
    if (m_theme == Theme::Dark) return QColor::fromRgb(error ? kDarkErrorPaper : kDarkPaper);
    return QColor::fromRgb(error ? kLightErrorPaper : kLightPaper);
}

std::optional<LineStylerLexer::LineFold> LineStylerLexer::foldLine(const QByteArray&, int) const {
    return std::nullopt;
}

void LineStylerLexer::styleText(int start, int end) {
    QsciScintilla* ed = editor();
    if (!ed) return;
    // Restyle whole lines: every language's rules look back to the start of the line.
    const int firstLine = int(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, start));
    const int lastLine = int(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, end));
    int state = firstLine > 0 ? int(ed->SendScintilla(QsciScintilla::SCI_GETLINESTATE, firstLine - 1)) : 0;
    QByteArray bytes;
    for (int line = firstLine; line <= lastLine; ++line) {
        const long lineStart = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line);
        const long lineEnd = ed->SendScintilla(QsciScintilla::SCI_GETLINEENDPOSITION, line);
        bytes.resize(lineEnd - lineStart + 1);
        ed->SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, lineStart, lineEnd, bytes.data());
        bytes.chop(1); // the terminating NUL
        const QByteArray styles = lineStyles(bytes);
        startStyling(int(lineStart));
        qsizetype runStart = 0;
        for (qsizetype k = 1; k <= styles.size(); ++k) {
            if (k == styles.size() || styles[k] != styles[runStart]) {
                setStyling(int(k - runStart), styles[runStart]);
                runStart = k;
            }
        }
        const long nextLine = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line + 1);
        if (nextLine > lineEnd) {
            startStyling(int(lineEnd));
            setStyling(int(nextLine - lineEnd), 0);
        }

        const std::optional<LineFold> fold = foldLine(bytes, state);
        if (!fold) continue;
        const int flags = fold->header ? QsciScintilla::SC_FOLDLEVELHEADERFLAG : 0;
        ed->SendScintilla(QsciScintilla::SCI_SETFOLDLEVEL, line,
                          (QsciScintilla::SC_FOLDLEVELBASE + fold->level) | flags);
        state = fold->state;
        ed->SendScintilla(QsciScintilla::SCI_SETLINESTATE, line, state);
    }
}

} // namespace editor
