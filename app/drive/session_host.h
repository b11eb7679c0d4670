// SessionHost: what a generic tool needs of whoever holds a drive's session — a family's workspace, or the
// main window for the BDS5 (its DriveConnection): the family, the DriveSession of the moment, and why the
// link may take nothing now. Plain functions, asked afresh each time: a reconnection replaces the session.
#pragma once

#include "drive_core/drive.h"

#include <QString>

#include <functional>

namespace serialport {
class DriveSession;
}

namespace app {

class DriveConnection;
class FamilyWorkspace;

struct SessionHost {
    drive_core::DriveFamily family = drive_core::DriveFamily::Bds5;
    std::function<serialport::DriveSession*()> session; // nullptr while not connected
    std::function<QString()> busyReason;                // why no poll may go now; "" when one may
    QString notConnected;                               // what to say without a session

    static SessionHost of(FamilyWorkspace& workspace);
    // The BDS5 of the main window: polls only at an interactive or monitor prompt, never during a transfer.
    static SessionHost of(DriveConnection& connection);
};

} // namespace app
