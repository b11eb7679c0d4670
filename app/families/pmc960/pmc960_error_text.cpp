// Pmc960ErrorText: #xx codes with the catalog's words, a severity and a hint.
#include "pmc960_error_text.h"

#include "errors/catalog_error_entry.h"

#include "drive_core/catalog/drive_catalog.h"

namespace app {

QString Pmc960ErrorText::codeText(int code) {
    return QStringLiteral("#%1").arg(code, 2, 16, QLatin1Char('0')).toUpper();
}

QString Pmc960ErrorText::hint(int code) {
    return catalogErrorHint(drive_core::DriveFamily::Pmc960, code);
}

ErrorLogModel::Entry Pmc960ErrorText::entry(int code, const QString& detail) {
    ErrorLogModel::Entry e = catalogErrorEntry(drive_core::DriveFamily::Pmc960, code);
    e.codeText = codeText(code);
    e.detail = detail;
    if (!drive_core::catalog::findError(drive_core::DriveFamily::Pmc960, code)) e.message = tr("Unknown error code");
    return e;
}

} // namespace app
