// The BDS5 lexer for the program editor: colours every token class the catalog knows (bds5_line_styler)
// and sets fold levels for IF/ELIF/ELSE/ENDIF blocks and label sections. Light and dark palettes.
#pragma once

#include "bds5_line_styler.h"
#include "line_styler_lexer.h"

namespace editor {

class Bds5Lexer final : public LineStylerLexer {
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

    // The theme comes from QSettings "options/theme" ("dark", else light), as the Options dialog saves it.
    explicit Bds5Lexer(QObject* parent = nullptr);

    static Theme themeFromSettings();

    const char* language() const override { return "BDS5"; }

    // The styles of one line, one entry per byte of its UTF-8 text. Pure; exposed for tests.
    static QByteArray styleLine(const QByteArray& line) { return styleBds5Line(line); }

protected:
    QByteArray lineStyles(const QByteArray& line) const override { return styleBds5Line(line); }
    std::optional<LineFold> foldLine(const QByteArray& line, int previousState) const override;
};

} // namespace editor
