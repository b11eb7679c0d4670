// servodesk-cli command execution: the verbs every family has.
#include "cli_runner.h"

#include "cli_files.h"

#include "drive_core/bds5/bds5_checker.h"
#include "drive_core/drive_factory.h"
#include "drive_core/pmc960/pmc960_checker.h"
#include "drive_core/sc750/sc750_compiler.h"
#include "serialport/axis_link.h"
#include "serialport/network_link.h"
#include "serialport/port_link.h"
#include "serialport/simulator_link.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace app::cli {

namespace {
constexpr double kSimulatorSpeed = 20; // --sim runs faster than real time where nothing waits on the clock
constexpr int kConnectTimeoutMs = 5000;

bool needsDrive(const CliCommand& c) {
    return c.kind != CliCommand::Kind::Check && c.kind != CliCommand::Kind::Compile;
}
} // namespace

QString familyDisplayName(drive_core::DriveFamily f) {
    return QString::fromLatin1(drive_core::familyTitle(f));
}

CliRunner::CliRunner(CliOptions options, QObject* parent) : QObject(parent), m_options(std::move(options)) {
    m_progressOnTty = ::isatty(STDERR_FILENO) != 0;
    m_deadline.setSingleShot(true);
    m_family = drive_core::familyFromName(m_options.drive.toStdString()).value_or(drive_core::DriveFamily::Bds5);
}

CliRunner::~CliRunner() {
    m_session.reset(); // the session refers to the link: it goes first
    m_link.reset();
    m_line.reset();
}

void CliRunner::start() {
    if (!drive_core::familyFromName(m_options.drive.toStdString()))
        return fail(kUsage, QStringLiteral("unknown drive \"%1\" (bds5, sc750 or pmc960)").arg(m_options.drive));
    if (!m_options.axis.isEmpty() && m_options.simulated)
        return fail(kUsage, QStringLiteral("--axis needs --port: the simulated drive of --sim is a single drive "
                                           "(servodesk-sim --axes serves a multidrop line)"));
    if (const QString problem = serialport::axisIdProblem(m_family, m_options.axis);
        !m_options.axis.isEmpty() && !problem.isEmpty())
        return fail(kUsage, QStringLiteral("--axis: %1").arg(problem));
    if (!watchNamesKnown()) return;
    if (std::any_of(m_options.commands.begin(), m_options.commands.end(), isMachineCommand))
        return machine(m_options.commands.front());
    for (const CliCommand& c : m_options.commands) {
        if (!needsDrive(c)) continue;
        return connectDrive();
    }
    next();
}

void CliRunner::connectDrive() {
    if (m_options.simulated) {
        // A record's trigger (--then "J 1000") goes out when the drive has accepted RECORD, a host round trip
        // later: at 20 times real time a 10 ms hiccup of a busy machine is 200 ms of drive time, a whole
        // recording missed. With a trigger the drive runs in real time, as a real one would; with a watch too,
        // whose samples are stamped by the host's clock.
        const bool realTime =
            std::any_of(m_options.commands.begin(), m_options.commands.end(), [](const CliCommand& c) {
                return !c.recordThen.isEmpty() || c.kind == CliCommand::Kind::Watch;
            });
        m_speed = realTime ? 1.0 : kSimulatorSpeed;
        m_link = std::make_unique<serialport::SimulatorLink>(m_family,
                                                             serialport::SimulatorLink::Options{m_speed, 9600, false});
    } else if (m_options.axis.isEmpty()) {
        m_link = serialport::makePortLink(m_options.port, m_options.baud, m_family);
    } else { // one axis of a multidrop line, selected by the family's addressing once the line is open
        m_line = serialport::makePortLink(m_options.port, m_options.baud, m_family);
        m_link = std::make_unique<serialport::AxisLink>(*m_line, m_family, m_options.axis);
    }
    m_session = serialport::makeDriveSession(m_family, *m_link);
    connect(m_session.get(), &serialport::DriveSession::linkFailed, this, [this](const QString& why) { fail(kNoAnswer, why); });
    connect(m_session.get(), &serialport::DriveSession::readyChanged, this, [this](bool ready) {
        if (ready && m_next == 0 && m_deadline.isActive()) {
            m_deadline.stop();
            next();
        }
    });
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        if (m_following) return;
        const QString who = m_options.axis.isEmpty()
                                ? QStringLiteral("the %1").arg(familyDisplayName(m_family))
                                : QStringLiteral("axis %1 of the %2 line (is a drive's address %1?)")
                                      .arg(m_options.axis, familyDisplayName(m_family));
        fail(kNoAnswer, QStringLiteral("no answer from %1 on %2 within %3 s")
                            .arg(who, m_link->description())
                            .arg(kConnectTimeoutMs / 1000));
    });
    m_deadline.start(kConnectTimeoutMs);
    m_link->open();
}

void CliRunner::next() {
    if (m_next >= m_options.commands.size()) return emit done(kOk);
    const CliCommand& c = m_options.commands[m_next++];
    switch (c.kind) {
    case CliCommand::Kind::Check: return check(c);
    case CliCommand::Kind::Compile: return compile(c);
    case CliCommand::Kind::Download:
    case CliCommand::Kind::Upload: return transfer(c);
    case CliCommand::Kind::VarsDump:
    case CliCommand::Kind::VarsSend: return vars(c);
    case CliCommand::Kind::Send: return sendLines(c.args, 0);
    case CliCommand::Kind::Run: return run(c);
    case CliCommand::Kind::Stop: return stop();
    case CliCommand::Kind::Record: return record(c);
    case CliCommand::Kind::Watch: return watch(c);
    case CliCommand::Kind::MachineScan:
    case CliCommand::Kind::MachineBackup:
    case CliCommand::Kind::MachineCompare:
    case CliCommand::Kind::MachineRestore: return machine(c);
    }
}

void CliRunner::fail(int code, const QString& reason) {
    if (m_failed) return; // the first reason is the one that matters; a closing port may add more
    m_failed = true;
    std::fprintf(stderr, "servodesk-cli: %s\n", qPrintable(reason));
    m_options.commands.clear();
    emit done(code);
}

void CliRunner::out(const QString& text) {
    std::fputs(text.toLocal8Bit().constData(), stdout);
    std::fflush(stdout);
}

void CliRunner::progress(const QString& text) {
    if (!m_progressOnTty) return;
    std::fprintf(stderr, "\r%s\033[K", qPrintable(text));
}

// check FILE: that family's diagnostics, FILE:LINE:COL: error: message (exit 1 if any).
void CliRunner::check(const CliCommand& c) {
    QString error;
    const auto text = readTextFile(c.args[0], error);
    if (!text) return fail(kUsage, error);
    QStringList found;
    const auto report = [&](int line, int column, const QString& what) {
        found << QStringLiteral("%1:%2:%3: error: %4").arg(c.args[0]).arg(line).arg(column).arg(what);
    };
    switch (m_family) {
    case drive_core::DriveFamily::Bds5:
        for (const auto& d : drive_core::bds5::checkProgram(programLines(*text))) {
            report(d.line, d.column + 1,
                   d.code ? QStringLiteral("ERR %1 '%2' %3")
                                .arg(d.code)
                                .arg(QString::fromStdString(d.entry), QString::fromStdString(d.message))
                          : QString::fromStdString(d.message));
        }
        break;
    case drive_core::DriveFamily::Sc750: // the compiler stops at the first error, as Motion Dialogue's did
        if (const auto compiled = drive_core::sc750::compile(text->toStdString()); !compiled.ok())
            report(compiled.error->line, compiled.error->column, QString::fromStdString(compiled.error->message));
        break;
    case drive_core::DriveFamily::Pmc960:
        for (const auto& d : drive_core::pmc960::checkProgram(text->toStdString()))
            report(d.line, d.column + 1,
                   d.code ? QStringLiteral("#%1 %2").arg(QString::number(d.code, 16).toUpper(),
                                                         QString::fromStdString(d.message))
                          : QString::fromStdString(d.message));
        break;
    }
    for (const QString& line : found) out(line + QLatin1Char('\n'));
    if (!found.isEmpty()) return fail(kDriveError, QStringLiteral("%1: %2 diagnostic(s)").arg(c.args[0]).arg(found.size()));
    next();
}

// compile FILE.BAS [-o FILE.BIN]: the SC750's compiler, as Compile > Compile in the IDE.
void CliRunner::compile(const CliCommand& c) {
    if (m_family != drive_core::DriveFamily::Sc750)
        return fail(kUsage, QStringLiteral("compile: the %1 runs its program text as it is; only the SC750's "
                                           "ServoBASIC is compiled (--drive sc750)")
                                .arg(familyDisplayName(m_family)));
    QString error;
    const auto text = readTextFile(c.args[0], error);
    if (!text) return fail(kUsage, error);
    const auto compiled = drive_core::sc750::compile(text->toStdString());
    if (!compiled.ok()) {
        out(QStringLiteral("%1:%2:%3: error: %4\n")
                .arg(c.args[0])
                .arg(compiled.error->line)
                .arg(compiled.error->column)
                .arg(QString::fromStdString(compiled.error->message)));
        return fail(kDriveError, QStringLiteral("%1: compile error").arg(c.args[0]));
    }
    const QFileInfo source(c.args[0]);
    const QString binPath =
        !c.output.isEmpty() ? c.output : source.dir().filePath(source.completeBaseName() + QStringLiteral(".BIN"));
    if (!writeBinaryFile(binPath, QByteArray(reinterpret_cast<const char*>(compiled.bin.data()), qsizetype(compiled.bin.size())),
                         error))
        return fail(kUsage, error);
    out(QStringLiteral("Compiled: %1 bytes of code, %2 bytes of data, written to %3\n")
            .arg(compiled.program.codeBytes())
            .arg(compiled.program.dataBytes())
            .arg(binPath));
    next();
}

// download FILE / upload FILE: the family's verified download and its upload, one result type.
void CliRunner::transfer(const CliCommand& c) {
    const bool download = c.kind == CliCommand::Kind::Download;
    QString error;
    std::optional<QString> text;
    if (download) {
        text = readTextFile(c.args[0], error);
        if (!text) return fail(kUsage, error);
    }
    auto* guard = new QObject(this);
    connect(m_session.get(), &serialport::DriveSession::transferProgress, guard, [this](qint64 done, qint64 total) {
        progress(total > 0 ? QStringLiteral("%1/%2").arg(done).arg(total) : QStringLiteral("%1").arg(done));
    });
    connect(m_session.get(), &serialport::DriveSession::transferFinished, guard,
            [this, guard, c, download](const serialport::TransferResult& r) {
                guard->deleteLater();
                progress(QString());
                for (const auto& e : r.errors) out(QStringLiteral("%1:%2: %3\n").arg(c.args[0]).arg(e.sourceLine).arg(e.text));
                if (!r.ok())
                    return fail(kDriveError, QStringLiteral("%1 The drive holds %2.").arg(r.message, r.driveHolds));
                QString why;
                if (!download && !writeTextFile(c.args[0], r.lines.join(QLatin1Char('\n')) + QLatin1Char('\n'), why))
                    return fail(kUsage, why);
                if (!r.errors.isEmpty()) return fail(kDriveError, r.message);
                out(r.message + QLatin1Char('\n'));
                next();
            });
    if (download)
        m_session->download(*text);
    else
        m_session->upload();
}

// send LINE...: each line at the drive's prompt (SC750: NAME, NAME=VALUE or a function); the answers on
// stdout; a drive error stops the run.
void CliRunner::sendLines(const QStringList& lines, int index) {
    if (index >= lines.size()) return next();
    auto* guard = new QObject(this);
    const quint64 id = m_session->sendLine(lines[index]);
    connect(m_session.get(), &serialport::DriveSession::answered, guard,
            [this, guard, id, lines, index](quint64 done, const serialport::LineAnswer& a) {
                if (done != id) return;
                guard->deleteLater();
                for (const QString& l : a.lines) out(l + QLatin1Char('\n'));
                if (!a.ok())
                    return fail(kDriveError, QStringLiteral("the drive refused \"%1\": %2").arg(lines[index], a.error));
                sendLines(lines, index + 1);
            });
    connect(m_session.get(), &serialport::DriveSession::lost, guard, [this, guard, id](quint64 done, const QString& why) {
        if (done != id) return;
        guard->deleteLater();
        fail(kNoAnswer, why);
    });
}

// run [LABEL] [--follow S]: the family's run command; with --follow the program's output is printed until
// it ends or S seconds of drive time have passed (it goes on running).
void CliRunner::run(const CliCommand& c) {
    auto* guard = new QObject(this);
    const bool follow = c.followSeconds > 0;
    connect(m_session.get(), &serialport::DriveSession::programOutput, guard, [this, follow](const QString& text) {
        if (follow) out(text);
    });
    connect(m_session.get(), &serialport::DriveSession::programStarted, guard, [this, guard, follow] {
        if (follow) return;
        guard->deleteLater();
        next();
    });
    connect(m_session.get(), &serialport::DriveSession::programEnded, guard,
            [this, guard](bool error, const QString& message) {
                guard->deleteLater();
                m_deadline.stop();
                m_following = false;
                if (error) return fail(kDriveError, QStringLiteral("the program stopped: %1").arg(message));
                next();
            });
    if (follow) {
        m_following = true;
        connect(&m_deadline, &QTimer::timeout, guard, [this, guard] {
            guard->deleteLater();
            m_following = false;
            next();
        });
        m_deadline.start(int(c.followSeconds * 1000 / m_speed));
    }
    m_session->run(c.args.value(0));
}

// stop: the family's urgent stop, ahead of anything queued; done when the drive is ready again.
void CliRunner::stop() {
    auto* guard = new QObject(this);
    connect(m_session.get(), &serialport::DriveSession::readyChanged, guard, [this, guard](bool ready) {
        if (!ready) return;
        guard->deleteLater();
        next();
    });
    QTimer::singleShot(2000, guard, [this, guard] { // a stop at the prompt changes nothing visible
        guard->deleteLater();
        next();
    });
    m_session->stop();
}

} // namespace app::cli
