// The BDS5 lexer for the program editor: colours every token class the catalog knows (bds5_line_styler)
// and sets fold levels for IF/ELIF/ELSE/ENDIF blocks and label sections. Light and dark palettes.
#pragma once

#include "bds5_line_styler.h"

#include <Qsci/qscilexercustom.h>

namespace editor {

class Bds5Lexer final : public QsciLexerCustom {
    Q_OBJECT
public:
    // Style numbers are the Bds5Style values; these aliases keep call sites short.
    enum Style {
        Default = Bds5Default,
        Comment = Bds5Comment,
        String = Bds5String,
        Label = Bds5Label,
        Number = Bds5Number,
        Command = Bds5Command,
        Keyword = Bds5Keyword,
        Variable = Bds5Variable,
        Switch = Bds5Switch,
        Constant = Bds5Constant,
        Condition = Bds5Condition,
        Operator = Bds5Operator,
        Error = Bds5Error,
    };
    enum class Theme { Light, Dark };

    // The theme comes from QSettings "options/theme" ("dark", else light), as the Options dialog saves it.
    explicit Bds5Lexer(QObject* parent = nullptr);

    static Theme themeFromSettings();
    Theme theme() const { return m_theme; }
    // Changes the palette and reapplies it (see applyStyles).
    void setTheme(Theme theme);
    // Gives every style its colour, paper and font (bold commands and labels, italic comments) on top of
    // the editor's base font. Call after installing the lexer: ProgramEditor::setLanguageLexer sets one
    // font and a white paper for all styles.
    void applyStyles(const QFont& base);
    // The editor's background and foreground for the theme.
    QColor paper() const;
    QColor foreground() const;

    QColor defaultPaper(int style) const override;

    const char* language() const override { return "BDS5"; }
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    void styleText(int start, int end) override;

    // The styles of one line, one entry per byte of its UTF-8 text. Pure; exposed for tests.
    static QByteArray styleLine(const QByteArray& line) { return styleBds5Line(line); }

private:
    Theme m_theme;
    QFont m_base;
};

} // namespace editor
