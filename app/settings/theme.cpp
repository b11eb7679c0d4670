// Theme: colour sets and how they are applied.
#include "theme.h"

#include "editor/bds5_language.h"

#include "terminal_widget.h"

#include <Qsci/qscilexer.h>
#include <Qsci/qsciscintilla.h>

#include <QLabel>
#include <QVariantList>

namespace app {

namespace {
const QColor kDarkPaper(0x1e, 0x1f, 0x22);
const QColor kDarkText(0xd8, 0xd8, 0xd4);
const QColor kDarkMargin(0x2a, 0x2b, 0x2f);
const QColor kDarkMarginText(0x8a, 0x8c, 0x92);
const QColor kDarkCaretLine(0x2c, 0x33, 0x3d);
const QColor kLightTerminal(0xfb, 0xfb, 0xf7);
const QColor kLightTerminalText(0x1c, 0x1c, 0x1c);
constexpr int kMaxStyle = 128;
constexpr int kLineNumberStyle = 33; // STYLE_LINENUMBER
const char* const kSaved = "servodeskLightColours";

// The light look as the editor set it up: [margin bg, margin fg, caret line, caret, per-style fg/bg...].
QVariantList lightColours(QsciScintilla& editor) {
    QVariantList saved = editor.property(kSaved).toList();
    if (!saved.isEmpty()) return saved;
    auto colour = [&editor](unsigned message, unsigned long arg = 0) {
        const long bgr = editor.SendScintilla(message, arg);
        return QColor(int(bgr & 0xff), int((bgr >> 8) & 0xff), int((bgr >> 16) & 0xff));
    };
    saved << editor.marginBackgroundColor(0) << colour(QsciScintillaBase::SCI_STYLEGETFORE, kLineNumberStyle)
          << colour(QsciScintillaBase::SCI_GETCARETLINEBACK) << colour(QsciScintillaBase::SCI_GETCARETFORE);
    if (QsciLexer* lexer = editor.lexer())
        for (int style = 0; style < kMaxStyle; ++style) saved << lexer->color(style) << lexer->paper(style);
    editor.setProperty(kSaved, saved);
    return saved;
}
} // namespace

QColor Theme::forDarkBackground(const QColor& colour) {
    float h = 0, s = 0, l = 0;
    colour.getHslF(&h, &s, &l);
    if (l < 0.5f) l = 0.62f + (0.5f - l) * 0.5f; // dark ink becomes light ink
    return QColor::fromHslF(h, s, std::min(l, 0.88f));
}

QColor Theme::stepHighlight(AppOptions::Theme theme) {
    return theme == AppOptions::Theme::Dark ? QColor(0x5c, 0x4a, 0x12) : QColor(0xff, 0xe0, 0x8a);
}

void Theme::applyToTerminal(TerminalWidget& terminal, AppOptions::Theme theme) {
    if (theme == AppOptions::Theme::Dark)
        terminal.setColours(kDarkPaper, kDarkText);
    else
        terminal.setColours(kLightTerminal, kLightTerminalText);
}

void Theme::applyToEditor(QsciScintilla& editor, AppOptions::Theme theme) {
    const bool dark = theme == AppOptions::Theme::Dark;
    if (!dark && editor.property(kSaved).isNull()) return; // never darkened: already light
    const QVariantList light = lightColours(editor);
    editor.setMarginsBackgroundColor(dark ? kDarkMargin : light[0].value<QColor>());
    editor.setMarginsForegroundColor(dark ? kDarkMarginText : light[1].value<QColor>());
    editor.setCaretLineBackgroundColor(dark ? kDarkCaretLine : light[2].value<QColor>());
    editor.setCaretForegroundColor(dark ? kDarkText : light[3].value<QColor>());
    // A BDS5 editor has its own light and dark palettes; other lexers are recoloured from their saved light ones.
    if (auto* language = editor::Bds5Language::of(&editor)) {
        language->setTheme(dark ? editor::Bds5Lexer::Theme::Dark : editor::Bds5Lexer::Theme::Light);
        return;
    }
    QsciLexer* lexer = editor.lexer();
    if (!lexer) {
        editor.setPaper(dark ? kDarkPaper : QColor(Qt::white));
        editor.setColor(dark ? kDarkText : QColor(Qt::black));
        return;
    }
    for (int style = 0; style < kMaxStyle && 4 + 2 * style + 1 < light.size(); ++style) {
        const QColor fg = light[4 + 2 * style].value<QColor>();
        const QColor bg = light[4 + 2 * style + 1].value<QColor>();
        lexer->setColor(dark ? forDarkBackground(fg) : fg, style);
        lexer->setPaper(dark ? kDarkPaper : bg, style);
    }
}

void Theme::showStatus(QLabel& label, const QString& text, bool error) {
    label.setText(text);
    label.setStyleSheet(error ? QStringLiteral("color: #b3261e;") : QString());
}

} // namespace app
