// What each byte of a PMC-960 MPL line is, for colouring: MPL is highlighted by character class, not by
// keywords (digest §10, §12) — command letters, labels, numbers (hex where the command takes hex), signs
// and triggers, sync and display characters. Plus a program check: unknown commands, labels that no
// @line defines, the 1,940-byte buffer. Pure functions; any thread.
#pragma once

#include <QByteArray>
#include <QList>
#include <QString>

namespace editor {

enum MplStyle : char {
    MplDefault = 0,
    MplComment, // the text after @<label>, @. lines
    MplLabel,   // @X, the label of B F L P, TLB/TLP/TLV/THI values
    MplCommand, // A, SM, TGP, THC, the TG register letters, L's X/Y/Z
    MplNumber,  // digits; hex digits where the command takes hex (conditions, OB, SP, THC, TGE, R counts)
    MplSign,    // + - * : (postfix signs that start or stop motion, the fixed-point colon)
    MplSync,    // , ; ^
    MplDisplay, // ? ! % &
    MplError,   // a character the controller would reject here
    MplStyleCount
};

// The style of every byte of one line (no terminator needed).
QByteArray styleMplLine(const QByteArray& line);

struct MplDiagnostic {
    int line = 0;   // 0-based
    int column = 0; // 0-based byte
    QString message;
};

// Checks a whole program as the controller would store it: unknown characters, branches to labels that
// no line defines (#C2 when run), the size without spaces (#C1 beyond 1,940 bytes).
QList<MplDiagnostic> checkMplProgram(const QByteArray& text);

} // namespace editor
