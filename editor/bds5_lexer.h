// A small BDS5 lexer for the program editor: comments, quoted strings, labels and numbers.
// Line by line and stateless (no BDS5 construct spans lines). Keywords come with the catalog (issue 5).
#pragma once

#include <Qsci/qscilexercustom.h>

namespace editor {

class Bds5Lexer final : public QsciLexerCustom {
    Q_OBJECT
public:
    enum Style { Default = 0, Comment, String, Label, Number };

    explicit Bds5Lexer(QObject* parent = nullptr);

    const char* language() const override { return "BDS5"; }
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    void styleText(int start, int end) override;

    // The styles of one line, one entry per byte of its UTF-8 text. Pure; exposed for tests.
    static QByteArray styleLine(const QByteArray& line);
};

} // namespace editor
