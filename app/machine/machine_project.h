// MachineProject: a machine's axes in one text file (issue 21), made to be read, diffed and kept in version
// control beside the files it names. The file ("machine.sdm"):
//
//   # ServoDesk machine project       '#' starts a comment line; blank lines are ignored
//   machine Line 3 palletiser         the machine's name (optional)
//   port /dev/ttyUSB0 9600            the line the axes share: a port name or URL, and the baud rate
//   backed-up 2026-11-28T08:12:03     when the files were read from the drives (a backup writes it)
//   axis A bds5 axis-A.bds axis-A.var one line per axis: ID, family, program file, variable file
//
// File names are relative to the project file's folder and have no blanks. An axis's program file may be
// "-" when the axis has no program kept. Parsing is strict: an unknown word, a repeated ID, an ID the family
// cannot have, or two families on one line is an error naming the line.
#pragma once

#include "drive_core/drive.h"

#include <QList>
#include <QString>

#include <optional>

namespace app::machine {

struct MachineAxis {
    QString id;
    drive_core::DriveFamily family = drive_core::DriveFamily::Bds5;
    QString programFile;   // relative to the project's folder; "" when none is kept
    QString variablesFile; // relative to the project's folder
};

struct MachineProject {
    static QString fileName() { return QStringLiteral("machine.sdm"); }

    QString name;
    QString port;
    int baud = 9600;
    QString backedUp; // ISO date and time of the backup, "" if not from one
    QList<MachineAxis> axes;

    // The file names a backup gives an axis: axis-A.bds and axis-A.var (the family's own suffixes).
    static MachineAxis axisNamed(const QString& id, drive_core::DriveFamily family);
    static QString programSuffix(drive_core::DriveFamily family); // "bds", "bas", "mpl"

    static std::optional<MachineProject> parse(const QString& text, QString& error);
    QString toText() const;

    // The family of every axis (a line carries one family), Bds5 when there are none.
    drive_core::DriveFamily family() const;
    const MachineAxis* axis(const QString& id) const;
};

// Reads dir/machine.sdm; nullopt with error ("dir/machine.sdm:4: ...") when missing or malformed.
std::optional<MachineProject> readMachineProject(const QString& dir, QString& error);

} // namespace app::machine
