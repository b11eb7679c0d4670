// servodesk-cli's engine: opens one connection (a fresh simulated drive, or a port) and runs the commands
// in order through the family's DriveSession, the same contract and transfers as the IDE's. Event-driven:
// main() runs the event loop and exits with done()'s code. stdout carries machine-readable output, stderr
// progress and reasons. The verbs are the same for every family as far as the drive allows (issue 17): vars
// reads and writes each family's own file (cli_bds5.cpp, cli_vars.cpp), watch polls every
// family (cli_watch.cpp); record (RECORD/PLAY) is the BDS5's alone.
#pragma once

#include "cli_options.h"

#include "drive_core/drive.h"
#include "serialport/drive_session.h"
#include "serialport/link.h"

#include <QByteArray>
#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>

namespace serialport {
class Bds5Session;
class Bds5Transfer;
struct Bds5TransferResult;
} // namespace serialport

namespace app::cli {

QString familyDisplayName(drive_core::DriveFamily family); // "BDS5", "SC750", "PMC-960"
bool isMachineCommand(const CliCommand& c);

class CliRunner final : public QObject {
    Q_OBJECT
public:
    explicit CliRunner(CliOptions options, QObject* parent = nullptr);
    ~CliRunner() override;

    void start();

    enum ExitCode { kOk = 0, kDriveError = 1, kUsage = 2, kNoAnswer = 3 };

signals:
    void done(int exitCode);

private:
    void connectDrive();
    void next();
    void fail(int code, const QString& reason);
    void out(const QString& text);
    void progress(const QString& text);

    void check(const CliCommand& c);
    void compile(const CliCommand& c);
    void transfer(const CliCommand& c);
    void sendLines(const QStringList& lines, int index);
    void run(const CliCommand& c);
    void stop();
    void vars(const CliCommand& c);  // cli_vars.cpp
    void watch(const CliCommand& c); // cli_watch.cpp
    // cli_machine.cpp: scan, backup, compare, restore of every axis on a multidrop line
    void machine(const CliCommand& c);
    void machineScan(const CliCommand& c);
    void machineJob(const CliCommand& c);
    bool watchNamesKnown();          // fails with the family's names when a watch names another
    // The BDS5's own ways (cli_bds5.cpp).
    serialport::Bds5Session* bds5Session();
    void bds5Vars(const CliCommand& c);
    void record(const CliCommand& c);
    void play(const CliCommand& c);
    void bds5TransferDone(const CliCommand& c, const serialport::Bds5TransferResult& result);

    CliOptions m_options;
    drive_core::DriveFamily m_family = drive_core::DriveFamily::Bds5;
    std::size_t m_next = 0;
    std::unique_ptr<serialport::Link> m_line; // the multidrop line under m_link (an AxisLink) with --axis
    std::unique_ptr<serialport::Link> m_link;
    std::unique_ptr<serialport::DriveSession> m_session;
    QTimer m_deadline;
    bool m_following = false;
    bool m_failed = false;
    bool m_progressOnTty = false;
    double m_speed = 1; // simulated seconds per wall second
};

} // namespace app::cli
