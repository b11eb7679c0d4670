// catalogErrorEntry: one error log row from the common catalog, for every family.
#include "catalog_error_entry.h"

#include "drive_core/catalog/drive_catalog.h"

#include <QCoreApplication>

namespace app {

namespace {

namespace cat = drive_core::catalog;
using Level = ErrorLogModel::Level;

QString text(std::string_view view) {
    return QString::fromUtf8(view.data(), qsizetype(view.size()));
}

Level levelOf(cat::ErrorLevel level) {
    switch (level) {
    case cat::ErrorLevel::Info: return Level::Info;
    case cat::ErrorLevel::Warning: return Level::Warning;
    case cat::ErrorLevel::Error: return Level::Error;
    case cat::ErrorLevel::Fault: return Level::Fault;
    case cat::ErrorLevel::Firmware: return Level::Firmware;
    }
    return Level::Error;
}

QString notInTable(drive_core::DriveFamily family) {
    switch (family) {
    case drive_core::DriveFamily::Bds5: return QCoreApplication::translate("app", "Not in the BDS5's error table.");
    case drive_core::DriveFamily::Sc750: return QCoreApplication::translate("app", "Not in the SC750's fault table.");
    case drive_core::DriveFamily::Pmc960: return QCoreApplication::translate("app", "Not in the PMC-960's error list.");
    }
    return {};
}

} // namespace

QString catalogErrorHint(drive_core::DriveFamily family, int code) {
    const cat::ErrorEntry* e = cat::findError(family, code);
    if (!e) return notInTable(family);
    return text(e->whatToDo.empty() ? e->meaning : e->whatToDo);
}

ErrorLogModel::Entry catalogErrorEntry(drive_core::DriveFamily family, int code) {
    ErrorLogModel::Entry row;
    row.family = family;
    row.code = code;
    row.hint = catalogErrorHint(family, code);
    const cat::ErrorEntry* e = cat::findError(family, code);
    if (!e) {
        row.codeText = QString::number(code);
        row.severity = QCoreApplication::translate("app", "Error");
        return row;
    }
    row.codeText = QString::fromStdString(e->codeText);
    row.message = text(e->message);
    row.severity = text(e->severity);
    row.level = levelOf(e->level);
    row.explanation = e->meaning.empty() ? text(e->manualLines)
                                         : QStringLiteral("%1 (%2)").arg(text(e->meaning), text(e->manualLines));
    return row;
}

} // namespace app
