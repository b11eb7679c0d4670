// The MPL (PMC-960) lexer for the program editor: colours each character class mpl_line_styler finds and
// folds each @label routine. Light and dark palettes like the BDS5 lexer.
#pragma once

#include "line_styler_lexer.h"
#include "mpl_line_styler.h"

namespace editor {

class MplLexer final : public LineStylerLexer {
    Q_OBJECT
public:
    explicit MplLexer(QObject* parent = nullptr, Theme theme = Theme::Light);

    const char* language() const override { return "MPL"; }

    static QByteArray styleLine(const QByteArray& line) { return styleMplLine(line); }

protected:
    QByteArray lineStyles(const QByteArray& line) const override { return styleMplLine(line); }
    std::optional<LineFold> foldLine(const QByteArray& line, int previousState) const override;
};

} // namespace editor
