// makeDriveSession: the family's session behind the one contract.
#include "drive_session.h"

#include "bds5_drive_session.h"
#include "pmc960_drive_session.h"
#include "sc750_drive_session.h"

namespace serialport {

std::unique_ptr<DriveSession> makeDriveSession(drive_core::DriveFamily family, Link& link) {
    switch (family) {
    case drive_core::DriveFamily::Bds5: return std::make_unique<Bds5DriveSession>(link);
    case drive_core::DriveFamily::Sc750: return std::make_unique<Sc750DriveSession>(link);
    case drive_core::DriveFamily::Pmc960: return std::make_unique<Pmc960DriveSession>(link);
    }
    return nullptr;
}

} // namespace serialport
