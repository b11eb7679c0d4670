// The ServoBASIC Plus (.bas) lexer for the program editor: colours each token class
// servobasic_line_styler finds. No folding. GUI thread only.
#pragma once

#include "line_styler_lexer.h"
#include "servobasic_line_styler.h"

namespace editor {

class ServoBasicLexer final : public LineStylerLexer {
    Q_OBJECT
public:
    explicit ServoBasicLexer(QObject* parent = nullptr, Theme theme = Theme::Light);

    const char* language() const override { return "ServoBASIC"; }

    static QByteArray styleLine(const QByteArray& line) { return styleServoBasicLine(line); }

protected:
    QByteArray lineStyles(const QByteArray& line) const override { return styleServoBasicLine(line); }
};

} // namespace editor
