// servodesk-cli: the BDS5's own ways — .VAR files (DUMP and NAME value lines) and RECORD/PLAY to the scope's
// CSV — on the Bds5Session behind the DriveSession contract.
#include "cli_runner.h"

#include "cli_files.h"

#include "scope/capture_csv.h"
#include "scope/play_parser.h"
#include "serialport/bds5_drive_session.h"
#include "serialport/bds5_variables_from_drive.h"
#include "serialport/bds5_variables_to_drive.h"
#include "serialport/watch_choices.h"

#include <memory>
#include <string>
#include <vector>

namespace app::cli {

using serialport::Bds5Session;

serialport::Bds5Session* CliRunner::bds5Session() {
    auto* bds5 = dynamic_cast<serialport::Bds5DriveSession*>(m_session.get());
    return bds5 ? &bds5->bds5() : nullptr;
}

// vars dump FILE.VAR / vars send FILE.VAR: DUMP into Motion Link's .VAR, and its NAME value lines at the prompt
// (the other families': cli_vars.cpp).
void CliRunner::bds5Vars(const CliCommand& c) {
    Bds5Session* session = bds5Session();
    serialport::Bds5Transfer* t = nullptr;
    if (c.kind == CliCommand::Kind::VarsSend) {
        QString error;
        const auto text = readTextFile(c.args[0], error);
        if (!text) return fail(kUsage, error);
        t = new serialport::Bds5VariablesToDrive(*session, *text, this);
    } else {
        t = new serialport::Bds5VariablesFromDrive(*session, this);
    }
    connect(t, &serialport::Bds5Transfer::progress, this, [this](int done, int total) {
        progress(total > 0 ? QStringLiteral("%1/%2 lines").arg(done).arg(total) : QStringLiteral("%1 lines").arg(done));
    });
    connect(t, &serialport::Bds5Transfer::finished, this, [this, t, c](const serialport::Bds5TransferResult& r) {
        progress(QString());
        t->deleteLater();
        bds5TransferDone(c, r);
    });
    t->start();
}

void CliRunner::bds5TransferDone(const CliCommand& c, const serialport::Bds5TransferResult& r) {
    for (const auto& e : r.errors)
        out(QStringLiteral("%1:%2: ERR %3 '%4' %5\n")
                .arg(c.args.value(0))
                .arg(e.sourceLine)
                .arg(e.error.code)
                .arg(e.error.entry, e.error.message));
    if (!r.ok()) return fail(kDriveError, r.summary);
    QString error;
    if (c.kind == CliCommand::Kind::VarsDump &&
        !writeTextFile(c.args[0], r.lines.join(QLatin1Char('\n')) + QLatin1Char('\n'), error))
        return fail(kUsage, error);
    if (!r.errors.isEmpty()) return fail(kDriveError, r.summary);
    out(r.summary + QLatin1Char('\n'));
    next();
}

// record: RECORD n t vars, the optional trigger, wait n*t ms of drive time, then PLAY into the scope's CSV.
void CliRunner::record(const CliCommand& c) {
    Bds5Session* session = bds5Session();
    if (!session)
        return fail(kUsage, QStringLiteral("record: RECORD/PLAY is the BDS5's; \"watch --vars ... --every MS --for S "
                                           "--csv FILE\" polls this drive's values into the same CSV"));
    QStringList lines{QStringLiteral("RECORD %1 %2 %3")
                          .arg(c.recordCount)
                          .arg(c.recordIntervalMs)
                          .arg(c.variables.join(QLatin1Char(' ')))};
    if (!c.recordThen.isEmpty()) lines << c.recordThen;
    auto* guard = new QObject(this);
    auto left = std::make_shared<int>(int(lines.size())); // answers still to come
    connect(session, &Bds5Session::finished, guard,
            [this, guard, left, c](quint64, const serialport::Bds5Response& r) {
                if (!r.errors.isEmpty()) {
                    guard->deleteLater();
                    return fail(kDriveError, QStringLiteral("the drive refused \"%1\": ERR %2 %3")
                                                 .arg(r.command)
                                                 .arg(r.errors.first().code)
                                                 .arg(r.errors.first().message));
                }
                if (--*left > 0) return;
                guard->deleteLater();
                const int waitMs = int(double(c.recordCount) * c.recordIntervalMs / m_speed) + 200;
                progress(QStringLiteral("recording %1 samples").arg(c.recordCount));
                QTimer::singleShot(waitMs, this, [this, c] { play(c); });
            });
    connect(session, &Bds5Session::failed, guard, [this, guard](quint64, const QString& why) {
        guard->deleteLater();
        fail(kNoAnswer, why);
    });
    for (const QString& l : lines) session->send(l);
}

// PLAY's listing (its first line repeats the set-up, then one line per sample) parsed by the scope's own
// parser into a Capture and written as the scope's .CSV (scope/capture_csv.h): what Scope > Open reads.
void CliRunner::play(const CliCommand& c) {
    Bds5Session* session = bds5Session();
    const quint64 id = session->send(QStringLiteral("PLAY"));
    auto* guard = new QObject(this);
    connect(
        session, &Bds5Session::finished, guard, [this, guard, id, c](quint64 done, const serialport::Bds5Response& r) {
            if (done != id) return;
            guard->deleteLater();
            progress(QString());
            if (!r.errors.isEmpty())
                return fail(kDriveError,
                            QStringLiteral("PLAY: ERR %1 %2").arg(r.errors.first().code).arg(r.errors.first().message));
            std::vector<std::string> lines;
            for (const QString& l : r.lines) lines.push_back(l.toStdString());
            // The unit P prints a variable in (currents in %), as the IDE's scope names them.
            const auto unitOf = [](const std::string& name) {
                const auto choice =
                    serialport::findWatchChoice(drive_core::DriveFamily::Bds5, QString::fromStdString(name));
                return choice ? choice->unit.toStdString() : std::string();
            };
            const scope::PlayParseResult parsed = scope::parsePlay(lines, unitOf);
            if (!parsed.capture)
                return fail(kDriveError, QStringLiteral("PLAY: %1").arg(QString::fromStdString(parsed.error)));
            const std::size_t samples = parsed.capture->sampleCount();
            if (samples == 0) return fail(kDriveError, QStringLiteral("PLAY returned no samples"));
            QString error;
            if (!writeTextFile(c.csvPath, QString::fromStdString(scope::writeCsv(*parsed.capture)), error))
                return fail(kUsage, error);
            out(QStringLiteral("%1 samples of %2 written to %3\n")
                    .arg(samples)
                    .arg(c.variables.join(QLatin1Char(',')))
                    .arg(c.csvPath));
            next();
        });
}

} // namespace app::cli
