// Bds5ErrorText: BDS5 error lines with the catalog's words.
#include "bds5_error_text.h"

#include "errors/catalog_error_entry.h"

#include "drive_core/catalog/bds5_catalog.h"

namespace app {

QString Bds5ErrorText::fixHint(int code) {
    return catalogErrorHint(drive_core::DriveFamily::Bds5, code);
}

ErrorLogModel::Entry Bds5ErrorText::entry(const serialport::Bds5ErrorLine& error) {
    ErrorLogModel::Entry e = catalogErrorEntry(drive_core::DriveFamily::Bds5, error.code);
    if (drive_core::catalog::bds5::findError(error.code))
        e.explanation += QStringLiteral("\n\n") + e.hint;
    else
        e.severity = tr("Break"); // a code the table does not know stops a program as most errors do
    e.message = error.message;    // the drive's own words
    e.detail = error.entry;
    e.programLine = error.programLine;
    return e;
}

} // namespace app
