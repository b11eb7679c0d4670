// What each family offers to watch (poll while the drive works), from its catalog: the BDS5 every plain
// variable and switch P prints (the RECORD tuning signals first), the SC750 its numeric predefined variables
// and parameters (read-only state first), the PMC-960 the values its status polls answer. Units are the
// ones the drive prints the values in. Pure; any thread.
#pragma once

#include "drive_core/drive.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace serialport {

struct WatchChoice {
    QString name;  // what WatchPoller::poll() takes, upper case: "VFB", "POS.ERROR", "SF"
    QString label; // for a chooser or a legend: "Following error (SF!)"
    QString unit;  // "VEL", "RPM", "counts"; "" when the value has none
};

QList<WatchChoice> watchChoices(drive_core::DriveFamily family);
// The family's choice of that name, whatever its case; nullopt when the family offers none by it.
std::optional<WatchChoice> findWatchChoice(drive_core::DriveFamily family, const QString& name);
QStringList watchNames(drive_core::DriveFamily family);
// How a sample is read, for a chooser's tooltip ("P prints the ticked variables, ...").
QString watchMethod(drive_core::DriveFamily family);

} // namespace serialport
