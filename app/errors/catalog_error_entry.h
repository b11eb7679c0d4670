// An error log row from the common catalog (drive_core/catalog/drive_catalog.h): the code as the drive shows
// it, the catalog's words, the family's severity word and level, what to do and where the manual says so.
// The family's error text adds what only it knows (the BDS5's entry, the SC750's run-time line). Pure.
#pragma once

#include "error_log_model.h"

namespace app {

// A code the family's table does not know: `unknownMessage` as the message, "Not in the <family>'s error
// table." as what to do, level Error (it stops a program as most errors do).
ErrorLogModel::Entry catalogErrorEntry(drive_core::DriveFamily family, int code);
// The catalog's remedy, else its meaning, else "not in the table".
QString catalogErrorHint(drive_core::DriveFamily family, int code);

} // namespace app
