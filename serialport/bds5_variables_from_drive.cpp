// Bds5VariablesFromDrive: DUMP, parsed.
#include "bds5_variables_from_drive.h"

namespace serialport {

namespace {
constexpr int kNeedsDisabled = 51; // ERR 51: the drive must be disabled
} // namespace

Bds5VariablesFromDrive::Bds5VariablesFromDrive(Bds5Session& session, QObject* parent)
    : Bds5Transfer(session, parent) {}

void Bds5VariablesFromDrive::cancel() {
    Bds5Transfer::cancel();
    if (isRunning() && session()) session()->sendUrgent("\x1b");
}

void Bds5VariablesFromDrive::begin() {
    if (!sessionAtInteractivePrompt()) {
        Bds5TransferResult r;
        r.status = Bds5TransferResult::Status::Refused;
        r.summary =
            tr("The drive is not at its --> prompt (mode: %1): no variables were read. DUMP works only "
               "at the interactive prompt.")
                .arg(session() ? modeName(session()->mode()) : tr("not connected"));
        return finish(r);
    }
    emit stageChanged(tr("Reading the variables (DUMP)"));
    send(QStringLiteral("DUMP"));
    countLinesInto(0, 0);
}

void Bds5VariablesFromDrive::answered(const Bds5Response& response) {
    Bds5TransferResult r;
    if (isCancelling()) {
        r.status = Bds5TransferResult::Status::Cancelled;
        r.summary = tr("Reading the variables was cancelled; nothing on the drive was changed.");
        return finish(r);
    }
    for (const Bds5ErrorLine& e : response.errors)
        r.errors.append({0, 0, QStringLiteral("DUMP"), e});
    if (!response.errors.isEmpty()) {
        const Bds5ErrorLine& e = response.errors.first();
        r.status = Bds5TransferResult::Status::Refused;
        r.summary =
            e.code == kNeedsDisabled
                ? tr("The drive is enabled: DUMP lists the variables only while the drive is disabled "
                     "(ERR 51). Disable it (DIS, or Drive > Disable) and read again; nothing was changed.")
                : tr("The drive answered DUMP with %1; no variables were read.").arg(describeError(e));
        return finish(r);
    }
    m_variables = Bds5VariableFile::fromDump(response.lines);
    for (const Bds5Assignment& a : m_variables.assignments())
        r.lines.append(a.instruction());
    r.linesDone = int(r.lines.size());
    r.summary = tr("Read %n variable(s) from the drive (DUMP).", nullptr, r.linesDone);
    finish(r);
}

void Bds5VariablesFromDrive::lost(const QString& reason) {
    Bds5TransferResult r;
    r.status = Bds5TransferResult::Status::Failed;
    r.summary = tr("Reading the variables failed: %1. Nothing on the drive was changed.").arg(reason);
    finish(r);
}

} // namespace serialport
