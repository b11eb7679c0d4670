// servodesk-cli's command line: the connection (simulated drive or a port) and the commands to run, in
// order, on one connection. Pure parsing; no I/O.
#pragma once

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace app::cli {

struct CliCommand {
    enum class Kind { Check, Compile, Download, Upload, VarsDump, VarsSend, Send, Run, Stop, Record, Watch, MachineScan, MachineBackup,
                      MachineCompare, MachineRestore };
    Kind kind = Kind::Send;
    QStringList args;         // files, lines, label
    double followSeconds = 0; // run --follow
    QStringList variables;    // record --vars, watch --vars (upper case)
    int recordCount = 0;
    int recordIntervalMs = 0;
    QString recordThen;         // record --then "J 1000"
    int watchEveryMs = 0;       // watch --every: from one poll to the next, ms
    double watchForSeconds = 0; // watch --for
    QString csvPath;            // record --csv, watch --csv
    QString output;             // compile -o
    QString scanIds;            // machine scan/backup --ids (all of 0-9, A-Z when empty; comma-separated)
    int scanWaitMs = 100;       // machine scan --wait: how long a called ID may take to answer
};

struct CliOptions {
    QString drive = QStringLiteral("bds5");
    bool simulated = true; // --sim (the default) or --port
    QString port;
    int baud = 9600;
    QString axis; // --axis ID: the axis of a multidrop line to talk to ("" for a single drive)
    std::vector<CliCommand> commands;
    bool help = false;
};

// Parses argv (without the program name). nullopt with error set when the words are wrong.
std::optional<CliOptions> parseCliOptions(const QStringList& args, QString& error);

QString cliUsage();

} // namespace app::cli
