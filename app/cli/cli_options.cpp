// servodesk-cli argument parsing.
#include "cli_options.h"

#include "serialport/network_link.h"

namespace app::cli {

namespace {
bool isCommandWord(const QString& w) {
    static const QStringList kWords{QStringLiteral("check"),  QStringLiteral("compile"), QStringLiteral("download"),
                                    QStringLiteral("upload"), QStringLiteral("vars"),    QStringLiteral("send"),
                                    QStringLiteral("run"),    QStringLiteral("stop"),    QStringLiteral("record"),
                                    QStringLiteral("watch"),  QStringLiteral("machine")};
    return kWords.contains(w);
}
} // namespace

QString cliUsage() {
    return QStringLiteral(
        "usage: servodesk-cli [--drive bds5|sc750|pmc960] [--port PATH [--baud N] [--axis ID] | --sim] COMMAND ...\n"
        "  --port is a serial port (/dev/ttyUSB0), a pty, or a serial device server: tcp://HOST:PORT (raw)\n"
        "  or rfc2217://HOST:PORT (the server sets the line to --baud, 8N1)\n"
        "  --axis ID talks to one axis of a multidrop line: BDS5 \\ID (0-9, A-Z), SC750 /nnn (0-254),\n"
        "            PMC-960 <attn>ID (the THI ID)\n"
        "commands (several may follow one another; they run in order on one connection; the same for every\n"
        "family as far as the drive allows):\n"
        "  check FILE                         the family's diagnostics: FILE:LINE:COL: error: message\n"
        "  compile FILE.BAS [-o FILE.BIN]     SC750: compile ServoBASIC to the drive's .BIN\n"
        "  download FILE                      send the program and verify it on the drive (BDS5 read back +\n"
        "                                     P CHECKSUM, SC750 .BIN CRC-32, PMC-960 communications checksum)\n"
        "  upload FILE                        the drive's program into FILE (SC750: its stored source)\n"
        "  vars dump FILE                     the drive's variables or parameters into FILE: BDS5 .VAR (DUMP,\n"
        "                                     drive disabled), SC750 .PRM (its PARAMS block), PMC-960 .MPL (the\n"
        "                                     T table as the lines that set it, SW1 ... SW0)\n"
        "  vars send FILE                     each line of such a file to the drive; a refusal is printed as\n"
        "                                     FILE:LINE: and the rest still go (exit 1 if any)\n"
        "  send LINE...                       send lines, print the drive's answers (SC750: NAME reads,\n"
        "                                     NAME=VALUE writes, GO.VEL etc. call a function)\n"
        "  run [LABEL] [--follow SECONDS]     BDS5 RUN, SC750 R, PMC-960 B<label>; with --follow print what\n"
        "                                     the drive sends until the program ends or the time runs out\n"
        "  stop                               stop motion and the program (^X, Ctrl C, ESC)\n"
        "  record --vars V1,V2 --count N --interval MS [--then \"J 1000\"] --csv OUT.csv\n"
        "                                     BDS5: RECORD, trigger, PLAY, and write the scope's CSV\n"
        "  watch --vars V1,V2 --every MS --for SECONDS --csv OUT.csv\n"
        "                                     poll 1 to 4 values every MS ms for SECONDS s into the scope's CSV,\n"
        "                                     each row stamped when it was read (BDS5: P; SC750: G frames, e.g.\n"
        "                                     POSITION,VELOCITY; PMC-960: status polls G,SF,V,I); --sim then\n"
        "                                     runs the drive in real time\n"
        "  machine scan [--ids LIST] [--wait MS]\n"
        "                                     call each ID of the line (every ID the family has, or LIST) and\n"
        "                                     print one line per axis that answers: ID, family, its answer\n"
        "                                     (BDS5: mode and prompt);\n"
        "                                     an ID silent for MS ms (default 100) is taken as absent\n"
        "  machine backup DIR [--ids LIST]    read every axis's program and variables into DIR, with\n"
        "                                     DIR/machine.sdm naming them: the axes of LIST (e.g. A,B or\n"
        "                                     1,2,3), or those a scan of every ID finds\n"
        "  machine compare DIR                read every axis DIR/machine.sdm names and list each variable\n"
        "                                     and program line that differs from its files; exit 1 if any\n"
        "  machine restore DIR                send every axis its program and variables, read the variables\n"
        "                                     back and report what each drive holds; exit 1 unless all match\n"
        "                                     Each machine command runs alone on its call; compare and restore\n"
        "                                     use the project's port and family when --port is not given\n"
        "The default connection is --sim --drive bds5: a fresh simulated drive, faster than real time.\n"
        "Exit status: 0 success, 1 a drive error, mismatch or diagnostic, 2 bad usage, 3 no drive answer.\n");
}

std::optional<CliOptions> parseCliOptions(const QStringList& args, QString& error) {
    CliOptions o;
    int i = 0;
    const auto value = [&](const QString& name) -> std::optional<QString> {
        if (i + 1 >= args.size()) {
            error = QStringLiteral("%1 needs a value").arg(name);
            return std::nullopt;
        }
        return args[++i];
    };
    for (; i < args.size() && !isCommandWord(args[i]); ++i) {
        const QString& a = args[i];
        if (a == QLatin1String("--help") || a == QLatin1String("-h"))
            o.help = true;
        else if (a == QLatin1String("--sim"))
            o.simulated = true;
        else if (a == QLatin1String("--drive")) {
            const auto v = value(a);
            if (!v) return std::nullopt;
            o.drive = v->toLower();
        } else if (a == QLatin1String("--port")) {
            const auto v = value(a);
            if (!v) return std::nullopt;
            o.port = *v;
            o.simulated = false;
            if (const QString problem = serialport::NetworkLink::problem(o.port); !problem.isEmpty()) {
                error = problem;
                return std::nullopt;
            }
        } else if (a == QLatin1String("--axis")) {
            const auto v = value(a);
            if (!v) return std::nullopt;
            o.axis = v->toUpper(); // checked against the family's IDs once --drive is known (CliRunner::start)
        } else if (a == QLatin1String("--baud")) {
            const auto v = value(a);
            if (!v) return std::nullopt;
            bool ok = false;
            o.baud = v->toInt(&ok);
            if (!ok || o.baud < 300 || o.baud > 115200) {
                error = QStringLiteral("--baud %1 is not a baud rate").arg(*v);
                return std::nullopt;
            }
        } else {
            error = QStringLiteral("unknown option \"%1\"").arg(a);
            return std::nullopt;
        }
    }
    while (i < args.size()) {
        const QString word = args[i++];
        CliCommand c;
        // Arguments run to the next command word (send takes everything up to one); vars takes exactly two,
        // since its "send" would read as the next command.
        QStringList rest;
        if (word == QLatin1String("vars")) {
            while (i < args.size() && rest.size() < 2) rest << args[i++];
        }
        while (word != QLatin1String("vars") && i < args.size() && !isCommandWord(args[i])) rest << args[i++];
        if (word == QLatin1String("vars")) {
            if (rest.size() != 2 || (rest[0] != QLatin1String("dump") && rest[0] != QLatin1String("send"))) {
                error = QStringLiteral("vars needs \"dump FILE\" or \"send FILE\"");
                return std::nullopt;
            }
            c.kind = rest[0] == QLatin1String("dump") ? CliCommand::Kind::VarsDump : CliCommand::Kind::VarsSend;
            c.args = {rest[1]};
        } else if (word == QLatin1String("machine")) {
            const QString verb = rest.value(0);
            const bool scan = verb == QLatin1String("scan");
            if (scan) c.kind = CliCommand::Kind::MachineScan;
            else if (verb == QLatin1String("backup")) c.kind = CliCommand::Kind::MachineBackup;
            else if (verb == QLatin1String("compare")) c.kind = CliCommand::Kind::MachineCompare;
            else if (verb == QLatin1String("restore")) c.kind = CliCommand::Kind::MachineRestore;
            else {
                error = QStringLiteral("machine needs scan, backup DIR, compare DIR or restore DIR");
                return std::nullopt;
            }
            int k = 1;
            if (!scan) {
                if (rest.size() < 2 || rest[1].startsWith(QLatin1String("--"))) {
                    error = QStringLiteral("machine %1 needs the machine's folder: machine %1 DIR").arg(verb);
                    return std::nullopt;
                }
                c.args = {rest[k++]};
            }
            for (; k < rest.size(); ++k) {
                bool ok = true;
                if (rest[k] == QLatin1String("--ids") && k + 1 < rest.size() && c.kind != CliCommand::Kind::MachineCompare &&
                    c.kind != CliCommand::Kind::MachineRestore)
                    c.scanIds = rest[++k].toUpper();
                else if (rest[k] == QLatin1String("--wait") && k + 1 < rest.size() && scan) c.scanWaitMs = rest[++k].toInt(&ok);
                else ok = false;
                if (!ok || c.scanWaitMs < 1) {
                    error = scan ? QStringLiteral("machine scan takes --ids LIST and --wait MS, not \"%1\"").arg(rest[k])
                                 : QStringLiteral("machine %1 does not take \"%2\"").arg(verb, rest[k]);
                    return std::nullopt;
                }
            }
        } else if (word == QLatin1String("run")) {
            c.kind = CliCommand::Kind::Run;
            for (int k = 0; k < rest.size(); ++k) {
                if (rest[k] == QLatin1String("--follow") && k + 1 < rest.size())
                    c.followSeconds = rest[++k].toDouble();
                else
                    c.args << rest[k];
            }
            if (c.args.size() > 1) {
                error = QStringLiteral("run takes one label");
                return std::nullopt;
            }
        } else if (word == QLatin1String("record") || word == QLatin1String("watch")) {
            const bool record = word == QLatin1String("record");
            c.kind = record ? CliCommand::Kind::Record : CliCommand::Kind::Watch;
            if (rest.size() % 2 != 0) {
                error = QStringLiteral("%1: \"%2\" needs a value").arg(word, rest.last());
                return std::nullopt;
            }
            for (int k = 0; k + 1 < rest.size(); k += 2) {
                const QString& key = rest[k];
                const QString& v = rest[k + 1];
                if (key == QLatin1String("--vars"))
                    c.variables = v.toUpper().split(QLatin1Char(','), Qt::SkipEmptyParts);
                else if (key == QLatin1String("--csv"))
                    c.csvPath = v;
                else if (record && key == QLatin1String("--count"))
                    c.recordCount = v.toInt();
                else if (record && key == QLatin1String("--interval"))
                    c.recordIntervalMs = v.toInt();
                else if (record && key == QLatin1String("--then"))
                    c.recordThen = v;
                else if (!record && key == QLatin1String("--every"))
                    c.watchEveryMs = v.toInt();
                else if (!record && key == QLatin1String("--for"))
                    c.watchForSeconds = v.toDouble();
                else {
                    error = QStringLiteral("%1: unknown option \"%2\"").arg(word, key);
                    return std::nullopt;
                }
            }
            if (record &&
                (c.variables.isEmpty() || c.recordCount <= 0 || c.recordIntervalMs <= 0 || c.csvPath.isEmpty())) {
                error = QStringLiteral("record needs --vars, --count, --interval and --csv");
                return std::nullopt;
            }
            // At most 4: what the scope's CSV and the IDE's Watch Variables take.
            if (!record && (c.variables.isEmpty() || c.variables.size() > 4 || c.watchEveryMs <= 0 ||
                            c.watchForSeconds <= 0 || c.csvPath.isEmpty())) {
                error = QStringLiteral(
                    "watch needs --vars with 1 to 4 names, --every MS (> 0), --for SECONDS (> 0) and --csv");
                return std::nullopt;
            }
        } else {
            static const std::pair<const char*, CliCommand::Kind> kSimple[] = {
                {"check", CliCommand::Kind::Check},       {"compile", CliCommand::Kind::Compile},
                {"download", CliCommand::Kind::Download}, {"upload", CliCommand::Kind::Upload},
                {"send", CliCommand::Kind::Send},         {"stop", CliCommand::Kind::Stop}};
            for (const auto& [name, kind] : kSimple)
                if (word == QLatin1String(name)) c.kind = kind;
            if (c.kind == CliCommand::Kind::Compile) {
                const int o_at = int(rest.indexOf(QStringLiteral("-o")));
                if (o_at >= 0 && o_at + 1 < rest.size()) {
                    c.output = rest[o_at + 1];
                    rest.remove(o_at, 2);
                }
            }
            c.args = rest;
            const bool needsOne = c.kind == CliCommand::Kind::Check || c.kind == CliCommand::Kind::Compile ||
                                  c.kind == CliCommand::Kind::Download || c.kind == CliCommand::Kind::Upload;
            if ((needsOne && c.args.size() != 1) || (c.kind == CliCommand::Kind::Send && c.args.isEmpty()) ||
                (c.kind == CliCommand::Kind::Stop && !c.args.isEmpty())) {
                error = QStringLiteral("%1: wrong number of arguments").arg(word);
                return std::nullopt;
            }
        }
        o.commands.push_back(c);
    }
    if (o.commands.empty() && !o.help) {
        error = QStringLiteral("no command given");
        return std::nullopt;
    }
    return o;
}

} // namespace app::cli
