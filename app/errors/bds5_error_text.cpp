// Bds5ErrorText: BDS5 error lines with the catalog's words.
#include "bds5_error_text.h"

namespace app {

namespace cat = drive_core::catalog::bds5;

namespace {
QString text(std::string_view view) {
    return QString::fromLatin1(view.data(), qsizetype(view.size()));
}

ErrorLogModel::Level levelOf(cat::Severity severity) {
    using Level = ErrorLogModel::Level;
    switch (severity) {
    case cat::Severity::HistoryOnly: return Level::Info;
    case cat::Severity::Warning: return Level::Warning;
    case cat::Severity::Break: return Level::Error;
    case cat::Severity::Disable: return Level::Fault;
    case cat::Severity::Firmware: return Level::Firmware;
    }
    return Level::Error;
}
} // namespace

QString Bds5ErrorText::severityName(cat::Severity severity) {
    switch (severity) {
    case cat::Severity::HistoryOnly: return tr("Logged");
    case cat::Severity::Warning: return tr("Warning");
    case cat::Severity::Break: return tr("Break");
    case cat::Severity::Disable: return tr("Disable");
    case cat::Severity::Firmware: return tr("Firmware");
    }
    return {};
}

QString Bds5ErrorText::fixHint(int code) {
    const cat::ErrorInfo* info = cat::findError(code);
    if (!info) return tr("Not in the BDS5's error table.");
    return info->remedy.empty() ? text(info->meaning) : text(info->remedy);
}

ErrorLogModel::Entry Bds5ErrorText::entry(const serialport::Bds5ErrorLine& error) {
    const cat::ErrorInfo* info = cat::findError(error.code);
    // A code the table does not know stops a program like most errors do.
    const cat::Severity severity = info ? info->severity : cat::Severity::Break;
    ErrorLogModel::Entry e;
    e.family = drive_core::DriveFamily::Bds5;
    e.code = error.code;
    e.codeText = QString::number(error.code);
    e.message = error.message;
    e.detail = error.entry;
    e.severity = severityName(severity);
    e.level = levelOf(severity);
    e.hint = fixHint(error.code);
    if (info) e.explanation = QStringLiteral("%1\n\n%2 (%3)").arg(text(info->meaning), e.hint, text(info->manualLines));
    e.programLine = error.programLine;
    return e;
}

} // namespace app
