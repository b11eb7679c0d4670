// The MPL (PMC-960) lexer for the program editor: colours each character class mpl_line_styler finds and
// folds each @label routine. Light and dark palettes like the BDS5 lexer.
#pragma once

#include "mpl_line_styler.h"

#include <Qsci/qscilexercustom.h>

namespace editor {

class MplLexer final : public QsciLexerCustom {
    Q_OBJECT
public:
    enum class Theme { Light, Dark };

    explicit MplLexer(QObject* parent = nullptr, Theme theme = Theme::Light);

    void setTheme(Theme theme);
    Theme theme() const { return m_theme; }
    // Fonts (bold commands and labels, italic comments) on top of the editor's base font.
    void applyStyles(const QFont& base);

    const char* language() const override { return "MPL"; }
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QColor defaultPaper(int style) const override;
    void styleText(int start, int end) override;

    static QByteArray styleLine(const QByteArray& line) { return styleMplLine(line); }

private:
    Theme m_theme;
    QFont m_base;
};

} // namespace editor
