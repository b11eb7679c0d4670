// ServoBasicLexer: colours ServoBASIC Plus (.bas) in the program editor — statements and BASIC keywords,
// catalog functions, predefined variables and parameters, strings, numbers, comments (' and REM), labels.
// Keywords come from the drive_core SC750 catalog, not a copy. GUI thread (the styling helpers: any).
#pragma once

#include <Qsci/qscilexercustom.h>

#include <QByteArray>
#include <QString>

namespace app {

enum ServoBasicStyle : char {
    BasicDefault = 0,
    BasicComment,
    BasicString,
    BasicNumber,
    BasicKeyword,  // statements and reserved words: GO.VEL, IF, DIM, AS, INTEGER, PARAMS
    BasicFunction, // MID$, ABS, INKEY$
    BasicVariable, // predefined variables and parameters: RUN.SPEED, INP3, KVP
    BasicLabel,    // Loop_Again: at the start of a line
    BasicStyleCount
};

// What a word is: one of Keyword, Function, Variable, or Default for a user name. Case-insensitive.
ServoBasicStyle servoBasicWordStyle(const QByteArray& word);
// The style of every byte of one line (no terminator needed).
QByteArray styleServoBasicLine(const QByteArray& line);

class ServoBasicLexer final : public QsciLexerCustom {
    Q_OBJECT
public:
    explicit ServoBasicLexer(QObject* parent = nullptr);

    void applyStyles(const QFont& base);
    const char* language() const override { return "ServoBASIC"; }
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    void styleText(int start, int end) override;
};

} // namespace app
