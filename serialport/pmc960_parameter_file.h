// Pmc960ParameterFile: the PMC-960's parameter table kept on disk (servodesk-cli vars dump/send) as the MPL
// lines that set it, each built and checked by the parameter table's own code (pmc960_parameter_values.h).
//
// Format (the manual gives no parameter file; chosen: what a user types at the } prompt to restore it, so
// any terminal can send it too):
//   @.text      MPL's comment line (L1034): skipped, never sent; blank lines too
//   SW1         write enable for the non-volatile T table (L1701-1711); T lines before it get #D3
//   TGP16       one parameter a line, <name><value> as the table writes it (hex, labels, fixed point n:dddd)
//   SW0         write protection back on
// Written with the T table's stored (?) values, less the link's own settings (THB, THC, THI: the table
// leaves them read only, isReadOnlyFromHost) and labels never set (TL has no way to clear one). Read line by
// line: a line that is not a parameter the host may write, or whose value fails the catalog's base and
// limits, is a problem reported at its line and not sent; SW0/SW1 are taken as they stand.
#pragma once

#include "pmc960_parameter_values.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <vector>

namespace serialport {

struct Pmc960ParameterLine {
    int sourceLine = 0; // 1-based line of the file's text
    QString command;    // "TGP16", "SW1", without the CR
};

struct Pmc960ParameterProblem {
    int sourceLine = 0;
    QString text;    // the line
    QString message; // "TGP must lie within 0 - 255."
};

class Pmc960ParameterFile {
public:
    static Pmc960ParameterFile parse(const QString& text);

    // The parameters a backup holds, in catalog order: the T table less the ones the host leaves alone.
    static std::vector<const Pmc960Parameter*> backedUp();
    // The line that sets p to a value as its display shows it ("P-16" read as "16" gives "TGP16"); empty
    // when there is nothing to set (a label never set) or the value does not fit the catalog.
    static QString settingLine(const Pmc960Parameter& p, const QString& displayedValue);
    // "@.comment" lines (blanks become '_': the controller stores no spaces), SW1, the lines, SW0; LF ends.
    static QString toText(const QStringList& comments, const QStringList& settingLines);

    const QList<Pmc960ParameterLine>& lines() const { return m_lines; }
    const QList<Pmc960ParameterProblem>& problems() const { return m_problems; }

private:
    QList<Pmc960ParameterLine> m_lines;
    QList<Pmc960ParameterProblem> m_problems;
};

} // namespace serialport
