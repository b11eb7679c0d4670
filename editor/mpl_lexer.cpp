// MplLexer: palettes, whole-line styling, one fold level per @label routine.
#include "mpl_lexer.h"

#include <Qsci/qsciscintilla.h>

#include <QColor>

#include <array>

namespace editor {

namespace {

struct Palette {
    std::array<QRgb, MplStyleCount> ink;
    QRgb paper;
    QRgb errorPaper;
};

// Order of MplStyle: default, comment, label, command, number, sign, sync, display, error.
constexpr Palette kLight{
    {0x1f2328, 0x6e7781, 0x8250df, 0x0b57d0, 0x0a6b86, 0xcf6a00, 0x116329, 0x953800, 0xcf222e}, 0xffffff, 0xffebe9};
constexpr Palette kDark{
    {0xd4d4d4, 0x6a9955, 0xc586c0, 0x569cd6, 0xb5cea8, 0xd7ba7d, 0x4ec9b0, 0x9cdcfe, 0xf48771}, 0x1e1e1e, 0x4b1818};

const Palette& paletteOf(MplLexer::Theme theme) {
    return theme == MplLexer::Theme::Dark ? kDark : kLight;
}

} // namespace

MplLexer::MplLexer(QObject* parent, Theme theme) : QsciLexerCustom(parent), m_theme(theme) {}

void MplLexer::setTheme(Theme theme) {
    m_theme = theme;
    if (m_base != QFont()) applyStyles(m_base);
}

void MplLexer::applyStyles(const QFont& base) {
    m_base = base;
    setDefaultFont(base);
    setDefaultColor(defaultColor(MplDefault));
    setDefaultPaper(paletteOf(m_theme).paper);
    for (int style = 0; style < MplStyleCount; ++style) {
        QFont font = base;
        font.setBold(style == MplCommand || style == MplLabel);
        font.setItalic(style == MplComment);
        setFont(font, style);
        setColor(defaultColor(style), style);
        setPaper(defaultPaper(style), style);
    }
}

QString MplLexer::description(int style) const {
    switch (style) {
    case MplDefault: return tr("Default");
    case MplComment: return tr("Comment");
    case MplLabel: return tr("Label");
    case MplCommand: return tr("Command");
    case MplNumber: return tr("Number");
    case MplSign: return tr("Sign or trigger");
    case MplSync: return tr("Synchronisation");
    case MplDisplay: return tr("Display");
    case MplError: return tr("Invalid character");
    default: return {};
    }
}

QColor MplLexer::defaultColor(int style) const {
    const Palette& p = paletteOf(m_theme);
    return QColor::fromRgb(style >= 0 && style < MplStyleCount ? p.ink[std::size_t(style)] : p.ink[0]);
}

QColor MplLexer::defaultPaper(int style) const {
    const Palette& p = paletteOf(m_theme);
    return QColor::fromRgb(style == MplError ? p.errorPaper : p.paper);
}

void MplLexer::styleText(int start, int end) {
    QsciScintilla* ed = editor();
    if (!ed) return;
    const int firstLine = int(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, start));
    const int lastLine = int(ed->SendScintilla(QsciScintilla::SCI_LINEFROMPOSITION, end));
    QByteArray bytes;
    for (int line = firstLine; line <= lastLine; ++line) {
        const long lineStart = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line);
        const long lineEnd = ed->SendScintilla(QsciScintilla::SCI_GETLINEENDPOSITION, line);
        bytes.resize(lineEnd - lineStart + 1);
        ed->SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, lineStart, lineEnd, bytes.data());
        bytes.chop(1);
        const QByteArray styles = styleLine(bytes);
        startStyling(int(lineStart));
        qsizetype runStart = 0;
        for (qsizetype k = 1; k <= styles.size(); ++k) {
            if (k == styles.size() || styles[k] != styles[runStart]) {
                setStyling(int(k - runStart), styles[runStart]);
                runStart = k;
            }
        }
        const long eol = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line + 1);
        if (eol > lineEnd) {
            startStyling(int(lineEnd));
            setStyling(int(eol - lineEnd), MplDefault);
        }
        // Each @label line heads a routine: labels do not end routines (execution falls through), but
        // folding by routine is how the manual lays programs out.
        const bool header = bytes.startsWith('@');
        const int level = QsciScintilla::SC_FOLDLEVELBASE + (header ? 0 : 1);
        ed->SendScintilla(QsciScintilla::SCI_SETFOLDLEVEL, line,
                          level | (header ? QsciScintilla::SC_FOLDLEVELHEADERFLAG : 0));
    }
}

} // namespace editor
