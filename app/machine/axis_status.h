// Axis status: what the Axes panel shows of each axis a scan finds (issue 21) — enabled or not, its fault,
// and what the family tells of its program or model — read with lines every family's session takes
// (DriveSession::sendLine) and said in words. Pure: the reading is AxisErrand's.
//   BDS5     P READY, P FAULT, P CHECKSUM (L9953: the checksum to compare after a load)
//   SC750    MODEL, FWV, ENABLED, FAULTCODE (digest §4.4.2.3, §4.4.4.5-6)
//   PMC-960  SS! (the snapshot register; bit 7 DRVON: the servodrive enabled, L1639-1648)
#pragma once

#include "drive_core/drive.h"

#include <QString>
#include <QStringList>

namespace app::machine {

QStringList statusQueries(drive_core::DriveFamily family);
// answers: one per query, in order (the drive's printed value). "enabled, no fault, program checksum 65280".
QString statusText(drive_core::DriveFamily family, const QStringList& answers);

} // namespace app::machine
