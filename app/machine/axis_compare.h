// Axis compare: what differs between two copies of one axis — a drive and its archived files, or two
// archives — per variable (by name, in the family's variable file) and per program line (lines aligned by
// their longest common run, so an inserted line shows as one row, not as every line after it). Pure; no I/O.
#pragma once

#include "drive_core/drive.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace app::machine {

struct CompareRow {
    enum class Kind { Variable, ProgramLine };
    Kind kind = Kind::Variable;
    QString key;    // the variable's name, or the program line's number on the left ("" for a line only right)
    QString left;   // the file's value or line ("" when the file has none)
    QString right;  // the drive's (or the second archive's)
    int leftLine = 0;  // 1-based line in the left file, 0 when it has none
    int rightLine = 0; // 1-based line on the right
    bool differs = false;
};

// name -> value of a family's variable file, in file order (BDS5 .VAR, SC750 .PRM, PMC-960 setting lines).
struct NamedValue {
    QString name;
    QString value;
    int line = 0;
};
QList<NamedValue> namedValues(drive_core::DriveFamily family, const QString& fileText);

// Every variable either side names, in left order then right-only ones; values equal as numbers count equal
// ("3000" and "3000.0").
QList<CompareRow> compareVariables(drive_core::DriveFamily family, const QString& left, const QString& right);
// Every line of both programs, aligned; trailing blanks and the line ends do not count.
QList<CompareRow> compareProgram(const QStringList& left, const QStringList& right);

// "1 difference", "3 differences": what a report says, singular or plural as English has it.
inline QString counted(qsizetype n, const QString& one, const QString& many) {
    return QString::number(n) + QLatin1Char(' ') + (n == 1 ? one : many);
}

// The differing rows only.
QList<CompareRow> differences(const QList<CompareRow>& rows);

// The line that sets one variable on the drive, as the family's command line takes it ("VMAX 3000",
// "KVP=0.08", "TGP16").
QString settingLine(drive_core::DriveFamily family, const QString& name, const QString& value);
// The lines that set these variables, with what the family needs around them (the PMC-960's T table is
// written between SW1 and SW0, L1701-1711).
QStringList settingLines(drive_core::DriveFamily family, const QList<NamedValue>& values);
// The variables that set the line itself (BDS5 ADDR, BAUD, ABAUD: a new ADDR puts the axis to sleep at once,
// L5424), which a restore does not send: each axis keeps the ones it answers by. Compare still lists them.
QStringList linkSettings(drive_core::DriveFamily family);
// fileText without the lines that assign one of names.
QString withoutVariables(drive_core::DriveFamily family, const QString& fileText, const QStringList& names);
// fileText with name's value replaced (the line kept in place), or the assignment added at the end.
QString withValue(drive_core::DriveFamily family, const QString& fileText, const QString& name, const QString& value);

} // namespace app::machine
