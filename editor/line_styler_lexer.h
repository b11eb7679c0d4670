// LineStylerLexer: the one QScintilla lexer behind every drive language. It restyles whole lines, asking the
// language only for the style of each byte of a line (its line styler) and, where the language folds, for
// the fold level a line gets; fonts, inks and papers come from the language's style table. GUI thread only.
#pragma once

#include <Qsci/qscilexercustom.h>

#include <QByteArray>
#include <QFont>
#include <QRgb>

#include <optional>
#include <span>

namespace editor {

// One style of a language: its name in the Options (marked with QT_TRANSLATE_NOOP("editor::LineStylerLexer")),
// its ink on the light and the dark paper, its font, and whether it marks an error (a red paper).
struct LexerStyle {
    const char* description;
    QRgb lightInk;
    QRgb darkInk;
    bool bold = false;
    bool italic = false;
    bool error = false;
};

class LineStylerLexer : public QsciLexerCustom {
    Q_OBJECT
public:
    enum class Theme { Light, Dark };

    // What a line does to folding: its level above the base, whether it heads a fold, and the state the
    // next line starts from (kept in Scintilla's line state, so restyling can start at any line).
    struct LineFold {
        int level = 0;
        bool header = false;
        int state = 0;
    };

    // styles: one entry per style number, style 0 the default; it must outlive the lexer (a constant table).
    LineStylerLexer(std::span<const LexerStyle> styles, Theme theme, QObject* parent);

    Theme theme() const { return m_theme; }
    // Changes the palette and reapplies it (see applyStyles).
    void setTheme(Theme theme);
    // Gives every style its ink, paper and font (bold, italic) on top of the editor's base font. Call after
    // installing the lexer: ProgramEditor::setLanguageLexer sets one font and a white paper for all styles.
    void applyStyles(const QFont& base);
    // The editor's background and default ink for the theme.
    QColor paper() const;
    QColor foreground() const;

    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QColor defaultPaper(int style) const override;
    void styleText(int start, int end) override;

protected:
    // The style of every byte of one line (no terminator; the line end is styled 0 here).
    virtual QByteArray lineStyles(const QByteArray& line) const = 0;
    // The fold of one line given the state the line before left (0 before the first line); none when the
    // language does not fold.
    virtual std::optional<LineFold> foldLine(const QByteArray& line, int previousState) const;

private:
    std::span<const LexerStyle> m_styles;
    Theme m_theme;
    QFont m_base;
};

} // namespace editor
