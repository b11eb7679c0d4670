// MplLexer: the MPL style table and one fold level per @label routine.
#include "mpl_lexer.h"

#include <array>

namespace editor {

namespace {

#define STYLE_NAME(text) QT_TRANSLATE_NOOP("editor::LineStylerLexer", text)
// Order of MplStyle; the inks of the BDS5 lexer where the classes match.
constexpr std::array<LexerStyle, MplStyleCount> kStyles{{
    {STYLE_NAME("Default"), 0x1f2328, 0xd4d4d4},
    {STYLE_NAME("Comment"), 0x6e7781, 0x6a9955, false, true},
    {STYLE_NAME("Label"), 0x8250df, 0xc586c0, true},
    {STYLE_NAME("Command"), 0x0b57d0, 0x569cd6, true},
    {STYLE_NAME("Number"), 0x0a6b86, 0xb5cea8},
    {STYLE_NAME("Sign or trigger"), 0xcf6a00, 0xd7ba7d},
    {STYLE_NAME("Synchronisation"), 0x116329, 0x4ec9b0},
    {STYLE_NAME("Display"), 0x953800, 0x9cdcfe},
    {STYLE_NAME("Invalid character"), 0xcf222e, 0xf48771, false, false, true},
}};
#undef STYLE_NAME

} // namespace

MplLexer::MplLexer(QObject* parent, Theme theme) : LineStylerLexer(kStyles, theme, parent) {}

// Each @label line heads a routine: labels do not end routines (execution falls through), but folding by
// routine is how the manual lays programs out.
std::optional<LineStylerLexer::LineFold> MplLexer::foldLine(const QByteArray& line, int) const {
    const bool header = line.startsWith('@');
    return LineFold{header ? 0 : 1, header, 0};
}

} // namespace editor
