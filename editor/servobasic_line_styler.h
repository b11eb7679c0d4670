// What each byte of a ServoBASIC Plus (.bas) line is, for colouring: statements and BASIC keywords, catalog
// functions, predefined variables and parameters, strings, numbers, comments (' and REM), labels. The words
// come from the drive_core SC750 catalog, not a copy. Pure functions of one line (no construct spans lines);
// any thread.
#pragma once

#include <QByteArray>

namespace editor {

// Scintilla style numbers of the ServoBASIC lexer; one per token class.
enum ServoBasicStyle : char {
    BasicDefault = 0,
    BasicComment,  // ' ... and REM ...
    BasicString,   // "quoted text"
    BasicNumber,   // 100, 1.5, 2E3
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

} // namespace editor
