// Bds5Upload: <BDS and its listing.
#include "bds5_upload.h"

namespace serialport {

QStringList listingLines(const Bds5Response& response) {
    QStringList lines = response.text.split(QStringLiteral("\r\n"));
    if (!lines.isEmpty() && lines.last().isEmpty()) lines.removeLast(); // the last line's CR LF
    QStringList program;
    for (const QString& line : lines) {
        QString bare = line;
        while (bare.startsWith(QLatin1Char('\n')))
            bare.remove(0, 1);                            // the error preamble CR LF LF
        if (bare.startsWith(QLatin1Char('\a'))) continue; // an error line, not program text
        program.append(line);
    }
    return program;
}

Bds5Upload::Bds5Upload(Bds5Session& session, QObject* parent) : Bds5Transfer(session, parent) {}

void Bds5Upload::cancel() {
    Bds5Transfer::cancel();
    if (isRunning() && session()) session()->sendUrgent("\x1b");
}

void Bds5Upload::begin() {
    if (!sessionAtInteractivePrompt()) {
        Bds5TransferResult r;
        r.status = Bds5TransferResult::Status::Refused;
        r.summary = tr("The drive is not at its --> prompt (mode: %1): nothing was read. Stop the program "
                       "(Break) and try again.")
                        .arg(session() ? modeName(session()->mode()) : tr("not connected"));
        return finish(r);
    }
    emit stageChanged(tr("Reading the program from the drive"));
    send(QStringLiteral("<BDS"));
    countLinesInto(0, 0);
}

void Bds5Upload::answered(const Bds5Response& response) {
    Bds5TransferResult r;
    r.lines = listingLines(response);
    r.linesDone = int(r.lines.size());
    if (isCancelling()) {
        r.status = Bds5TransferResult::Status::Cancelled;
        r.summary =
            tr("Reading the program was cancelled after %n line(s); the drive's program is unchanged.",
               nullptr, r.linesDone);
        return finish(r);
    }
    if (!response.errors.isEmpty()) {
        r.status = Bds5TransferResult::Status::Failed;
        r.summary = tr("The drive answered <BDS with %1.").arg(describeError(response.errors.first()));
        for (const Bds5ErrorLine& e : response.errors)
            r.errors.append({0, 0, QStringLiteral("<BDS"), e});
        return finish(r);
    }
    r.summary = tr("Read %n line(s) from the drive (<BDS).", nullptr, r.linesDone);
    finish(r);
}

void Bds5Upload::lost(const QString& reason) {
    Bds5TransferResult r;
    r.status = Bds5TransferResult::Status::Failed;
    r.summary = tr("Reading the program failed: %1. The drive's program is unchanged.").arg(reason);
    finish(r);
}

} // namespace serialport
