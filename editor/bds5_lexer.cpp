// Bds5Lexer: palettes, styling in whole lines, and fold levels. Each line's state (inside a label
// section, IF depth) is kept in Scintilla's line state, so restyling can start at any line.
#include "bds5_lexer.h"

#include <Qsci/qsciscintilla.h>

#include <QColor>
#include <QSettings>

#include <algorithm>
#include <array>

namespace editor {

namespace {

struct Palette {
    std::array<QRgb, Bds5StyleCount> ink;
    QRgb paper;
    QRgb errorPaper;
};

// Light: GitHub-like inks on white. Dark: VS Code Dark+-like inks on #1e1e1e. Order of Bds5Style:
// default, comment, string, label, number, command, keyword, variable, switch, constant, condition,
// operator, error.
constexpr Palette kLight{{0x1f2328, 0x6e7781, 0x0a3069, 0x8250df, 0x0a6b86, 0x0b57d0, 0x0b57d0, 0x953800, 0x116329,
                          0x116329, 0x0b57d0, 0x57606a, 0xcf222e},
                         0xffffff,
                         0xffebe9};
constexpr Palette kDark{{0xd4d4d4, 0x6a9955, 0xce9178, 0xc586c0, 0xb5cea8, 0x569cd6, 0x569cd6, 0x9cdcfe, 0x4ec9b0,
                         0x4ec9b0, 0x569cd6, 0xb0b0b0, 0xf48771},
                        0x1e1e1e,
                        0x4b1818};

const Palette& paletteOf(Bds5Lexer::Theme theme) {
    return theme == Bds5Lexer::Theme::Dark ? kDark : kLight;
}

// Line state: bit 16 = inside a label section, low 16 bits = open IF blocks.
constexpr int kInLabelBit = 1 << 16;

} // namespace

Bds5Lexer::Bds5Lexer(QObject* parent) : QsciLexerCustom(parent), m_theme(themeFromSettings()) {}

Bds5Lexer::Theme Bds5Lexer::themeFromSettings() {
    // The Options dialog keeps it in "options/theme"; "ui/theme" is the older name.
    const QSettings settings;
    const QString theme =
        settings.value(QStringLiteral("options/theme"), settings.value(QStringLiteral("ui/theme"))).toString();
    return theme == QLatin1String("dark") ? Theme::Dark : Theme::Light;
}

void Bds5Lexer::setTheme(Theme theme) {
    m_theme = theme;
    if (m_base != QFont()) applyStyles(m_base);
}

void Bds5Lexer::applyStyles(const QFont& base) {
    m_base = base;
    setDefaultFont(base);
    setDefaultColor(foreground());
    setDefaultPaper(paper());
    for (int style = 0; style < Bds5StyleCount; ++style) {
        QFont font = base;
        font.setBold(style == Command || style == Label || style == Constant);
        font.setItalic(style == Comment);
        setFont(font, style);
        setColor(defaultColor(style), style);
        setPaper(defaultPaper(style), style);
    }
}

QColor Bds5Lexer::paper() const {
    return QColor::fromRgb(paletteOf(m_theme).paper);
}

QColor Bds5Lexer::foreground() const {
    return QColor::fromRgb(paletteOf(m_theme).ink[Default]);
}

QColor Bds5Lexer::defaultPaper(int style) const {
    const Palette& p = paletteOf(m_theme);
    return QColor::fromRgb(style == Error ? p.errorPaper : p.paper);
}

QString Bds5Lexer::description(int style) const {
    switch (style) {
    case Default: return tr("Default");
    case Comment: return tr("Comment");
    case String: return tr("String");
    case Label: return tr("Label");
    case Number: return tr("Number");
    case Command: return tr("Command");
    case Keyword: return tr("Keyword");
    case Variable: return tr("Variable");
    case Switch: return tr("Switch");
    case Constant: return tr("Constant");
    case Condition: return tr("Condition");
    case Operator: return tr("Operator");
    case Error: return tr("Unknown word");
    default: return {};
    }
}

QColor Bds5Lexer::defaultColor(int style) const {
    const Palette& p = paletteOf(m_theme);
    return QColor::fromRgb(style >= 0 && style < Bds5StyleCount ? p.ink[std::size_t(style)] : p.ink[Default]);
}

void Bds5Lexer::styleText(int start, int end) {
    QsciScintilla* ed = editor();
    if (!ed) return;
    // Restyle whole lines: the rules look back to the start of the line.
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
        const QByteArray styles = styleLine(bytes);
        startStyling(int(lineStart));
        qsizetype runStart = 0;
        for (qsizetype k = 1; k <= styles.size(); ++k) {
            if (k == styles.size() || styles[k] != styles[runStart]) {
                setStyling(int(k - runStart), styles[runStart]);
                runStart = k;
            }
        }

        // Fold levels: a label opens a section that the next label at the top level closes; IF opens a
        // block, ELIF/ELSE close the previous part and open the next, ENDIF is the block's last line.
        bool inLabel = (state & kInLabelBit) != 0;
        int depth = state & 0xffff;
        int level = depth + (inLabel ? 1 : 0);
        bool header = false;
        switch (bds5LineKind(bytes)) {
        case Bds5LineKind::Label:
            if (depth == 0) {
                level = 0;
                header = true;
                inLabel = true;
            }
            break;
        case Bds5LineKind::If:
            header = true;
            ++depth;
            break;
        case Bds5LineKind::Elif:
        case Bds5LineKind::Else:
            if (depth > 0) {
                --level;
                header = true;
            }
            break;
        case Bds5LineKind::Endif: depth = std::max(0, depth - 1); break;
        case Bds5LineKind::Plain: break;
        }
        const int flags = header ? QsciScintilla::SC_FOLDLEVELHEADERFLAG : 0;
        ed->SendScintilla(QsciScintilla::SCI_SETFOLDLEVEL, line, (QsciScintilla::SC_FOLDLEVELBASE + level) | flags);
        state = std::min(depth, 0xffff) | (inLabel ? kInLabelBit : 0);
        ed->SendScintilla(QsciScintilla::SCI_SETLINESTATE, line, state);
    }
}

} // namespace editor
