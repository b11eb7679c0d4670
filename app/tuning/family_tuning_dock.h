// The Tuning dock of a family tuned through a TuningProfile (SC750, PMC-960): the one TuningPanel over a
// FamilyTuningRunner, in a dock hidden
// until its menu action raises it among the terminal's tabs, as the BDS5's Tuning Panel. A workspace makes one,
// lists the dock in docks(), puts the action in its menu and attaches its session when it connects.
#pragma once

#include "drive_core/drive.h"

#include <QPointer>

class QAction;
class QDockWidget;

namespace serialport {
class DriveSession;
class Link;
} // namespace serialport

namespace app {

class TuningPanel;
class MainWindow;

struct FamilyTuningDock {
    QDockWidget* dock = nullptr;
    QPointer<TuningPanel> panel; // the window deletes its docks before the workspaces
    QAction* action = nullptr; // "Tuning &Panel", checkable
};

FamilyTuningDock makeFamilyTuningDock(MainWindow& window, drive_core::DriveFamily family);
// The workspace's connection (nullptr, nullptr when none); the gains are read once it is there.
void attachTuning(TuningPanel& panel, serialport::DriveSession* session, serialport::Link* link);

} // namespace app
