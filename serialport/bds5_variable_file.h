// Bds5VariableFile: Motion Link's .VAR variable set (L1057-1067, L1195-1203), read and written.
//
// Format (the manual gives none beyond "NAME value" assignments; chosen, and what DUMP prints):
//   NAME value        one assignment per line, value as the drive prints it (user units), e.g. "VMAX 3000";
//   NAME=value        also read (L9994-10009 sends both forms), as is "NAME = value";
//   CLEARX            the v3 command that zeroes X1-X250 and XS1-XS50 may stand on a line of its own (L9308);
//   ; text            a comment, at the start of a line or after a blank; DUMP's protected variables and
//                     program lines arrive this way and are never sent; blank lines are ignored.
// Written with one "NAME value" per line after a comment header. Any other line is a problem reported at
// its line number and not sent.
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

namespace serialport {

struct Bds5Assignment {
    int sourceLine = 0; // 1-based line of the file's text
    QString name;       // upper-case; "CLEARX" for the command
    QString value;      // as written; empty for CLEARX
    // The line sent to the drive: "NAME value" or "CLEARX".
    QString instruction() const { return value.isEmpty() ? name : name + QLatin1Char(' ') + value; }
};

struct Bds5VariableProblem {
    int sourceLine = 0;
    QString text;    // the line
    QString message; // "not an assignment (NAME value)"
};

class Bds5VariableFile {
public:
    static Bds5VariableFile parse(const QString& text);
    // The assignment lines of a DUMP answer (lines prefixed ';' are left out: protected variables, program).
    static Bds5VariableFile fromDump(const QStringList& dumpLines);

    // "; header" lines then one "NAME value" line each, LF line ends.
    QString toText(const QStringList& headerComments = {}) const;

    const QList<Bds5Assignment>& assignments() const { return m_assignments; }
    const QList<Bds5VariableProblem>& problems() const { return m_problems; }
    // The value assigned to name, last one wins; empty if none.
    QString valueOf(const QString& name) const;

private:
    QList<Bds5Assignment> m_assignments;
    QList<Bds5VariableProblem> m_problems;
};

} // namespace serialport
