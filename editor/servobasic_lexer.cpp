// ServoBasicLexer: the ServoBASIC style table.
#include "servobasic_lexer.h"

#include <array>

namespace editor {

namespace {

#define STYLE_NAME(text) QT_TRANSLATE_NOOP("editor::LineStylerLexer", text)
// Order of ServoBasicStyle; the inks of the BDS5 lexer where the classes match.
constexpr std::array<LexerStyle, BasicStyleCount> kStyles{{
    {STYLE_NAME("Default"), 0x1f2328, 0xd4d4d4},
    {STYLE_NAME("Comment"), 0x6e7781, 0x6a9955, false, true},
    {STYLE_NAME("String"), 0x0a3069, 0xce9178},
    {STYLE_NAME("Number"), 0x0a6b86, 0xb5cea8},
    {STYLE_NAME("Statement or keyword"), 0x0b57d0, 0x569cd6, true},
    {STYLE_NAME("Function"), 0x8250df, 0xc586c0},
    {STYLE_NAME("Predefined variable or parameter"), 0x953800, 0x9cdcfe},
    {STYLE_NAME("Label"), 0x116329, 0x4ec9b0, true},
}};
#undef STYLE_NAME

} // namespace

ServoBasicLexer::ServoBasicLexer(QObject* parent, Theme theme) : LineStylerLexer(kStyles, theme, parent) {}

} // namespace editor
