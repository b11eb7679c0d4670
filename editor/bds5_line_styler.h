// What each byte of a BDS5 line is, for colouring: the token classes of seed-bds5 §4.1-4.5 with the words
// looked up in the drive_core catalog, and what the line opens or closes (IF blocks, label sections) for
// folding. Pure functions of one line's text (no BDS5 construct spans lines); any thread.
#pragma once

#include <QByteArray>

namespace editor {

// Scintilla style numbers of the BDS5 lexer; one per token class.
enum Bds5Style : char {
    Bds5Default = 0,
    Bds5Comment,   // `; ...` at the line start or after a blank
    Bds5String,    // "quoted text"
    Bds5Label,     // 10$, POWER-UP$, A$
    Bds5Number,    // 1000, -5 (the digits), 0FFH, a print format [8.2]
    Bds5Command,   // MA, P, IF, ?, <BDS
    Bds5Keyword,   // a command's argument word: CW, CAM, HIST, START ...
    Bds5Variable,  // VMAX, X12, TMR1
    Bds5Switch,    // a switch variable: PROP, I3, O1, XS5
    Bds5Constant,  // ON OFF Y N
    Bds5Condition, // GT GE LT LE EQ NE
    Bds5Operator,  // + - * / & ! ( ) = :
    Bds5Error,     // a word the drive does not know, a malformed number (FFH), a stray character
    Bds5StyleCount
};

// What a line does to the block structure (folding, outline).
enum class Bds5LineKind { Plain, Label, If, Elif, Else, Endif };

// The style of every byte of one line of UTF-8 text (no line terminator needed; CR/LF stay Default).
QByteArray styleBds5Line(const QByteArray& line);

// The line's role in the block structure, from its first entry.
Bds5LineKind bds5LineKind(const QByteArray& line);

} // namespace editor
