// Bds5Lexer: the BDS5 style table and fold levels. A line's state (inside a label section, IF depth) is
// kept in Scintilla's line state, so restyling can start at any line.
#include "bds5_lexer.h"

#include <QSettings>

#include <algorithm>
#include <array>

namespace editor {

namespace {

#define STYLE_NAME(text) QT_TRANSLATE_NOOP("editor::LineStylerLexer", text)
// Light: GitHub-like inks on white. Dark: VS Code Dark+-like inks on #1e1e1e. Order of Bds5Style.
constexpr std::array<LexerStyle, Bds5StyleCount> kStyles{{
    {STYLE_NAME("Default"), 0x1f2328, 0xd4d4d4},
    {STYLE_NAME("Comment"), 0x6e7781, 0x6a9955, false, true},
    {STYLE_NAME("String"), 0x0a3069, 0xce9178},
    {STYLE_NAME("Label"), 0x8250df, 0xc586c0, true},
    {STYLE_NAME("Number"), 0x0a6b86, 0xb5cea8},
    {STYLE_NAME("Command"), 0x0b57d0, 0x569cd6, true},
    {STYLE_NAME("Keyword"), 0x0b57d0, 0x569cd6},
    {STYLE_NAME("Variable"), 0x953800, 0x9cdcfe},
    {STYLE_NAME("Switch"), 0x116329, 0x4ec9b0},
    {STYLE_NAME("Constant"), 0x116329, 0x4ec9b0, true},
    {STYLE_NAME("Condition"), 0x0b57d0, 0x569cd6},
    {STYLE_NAME("Operator"), 0x57606a, 0xb0b0b0},
    {STYLE_NAME("Unknown word"), 0xcf222e, 0xf48771, false, false, true},
}};
#undef STYLE_NAME

// Line state: bit 16 = inside a label section, low 16 bits = open IF blocks.
constexpr int kInLabelBit = 1 << 16;

} // namespace

Bds5Lexer::Bds5Lexer(QObject* parent) : LineStylerLexer(kStyles, themeFromSettings(), parent) {}

Bds5Lexer::Theme Bds5Lexer::themeFromSettings() {
    // The Options dialog keeps it in "options/theme"; "ui/theme" is the older name.
    const QSettings settings;
    const QString theme =
        settings.value(QStringLiteral("options/theme"), settings.value(QStringLiteral("ui/theme"))).toString();
    return theme == QLatin1String("dark") ? Theme::Dark : Theme::Light;
}

// A label opens a section that the next label at the top level closes; IF opens a block, ELIF/ELSE close
// the previous part and open the next, ENDIF is the block's last line.
std::optional<LineStylerLexer::LineFold> Bds5Lexer::foldLine(const QByteArray& line, int previousState) const {
    bool inLabel = (previousState & kInLabelBit) != 0;
    int depth = previousState & 0xffff;
    LineFold fold;
    fold.level = depth + (inLabel ? 1 : 0);
    switch (bds5LineKind(line)) {
    case Bds5LineKind::Label:
        if (depth == 0) {
            fold.level = 0;
            fold.header = true;
            inLabel = true;
        }
        break;
    case Bds5LineKind::If:
        fold.header = true;
        ++depth;
        break;
    case Bds5LineKind::Elif:
    case Bds5LineKind::Else:
        if (depth > 0) {
            --fold.level;
            fold.header = true;
        }
        break;
    case Bds5LineKind::Endif: depth = std::max(0, depth - 1); break;
    case Bds5LineKind::Plain: break;
    }
    fold.state = std::min(depth, 0xffff) | (inLabel ? kInLabelBit : 0);
    return fold;
}

} // namespace editor
