// servodesk-cli command execution.
#include "cli_runner.h"

#include "drive_core/bds5/bds5_checker.h"
#include "drive_core/catalog/bds5_catalog.h"
#include "drive_core/drive_factory.h"
#include "serialport/bds5_download.h"
#include "serialport/bds5_upload.h"
#include "serialport/bds5_variables_from_drive.h"
#include "serialport/bds5_variables_to_drive.h"
#include "serialport/serial_port_link.h"
#include "serialport/simulator_link.h"

#include <QFile>
#include <QSaveFile>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <unistd.h>

namespace app::cli {

using serialport::Bds5Session;

namespace {
constexpr double kSimulatorSpeed = 20; // --sim runs faster than real time where nothing waits on the clock
constexpr int kConnectTimeoutMs = 5000;

std::optional<QString> readFile(const QString& path, QString& error) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        error = QStringLiteral("cannot read %1: %2").arg(path, f.errorString());
        return std::nullopt;
    }
    return QString::fromLatin1(f.readAll()); // drive files are 7-bit ASCII; Latin-1 keeps any byte
}

bool writeFile(const QString& path, const QString& text, QString& error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text.toLatin1()) < 0 || !f.commit()) {
        error = QStringLiteral("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

bool needsDrive(const CliCommand& c) {
    return c.kind != CliCommand::Kind::Check && c.kind != CliCommand::Kind::Compile;
}
} // namespace

CliRunner::CliRunner(CliOptions options, QObject* parent) : QObject(parent), m_options(std::move(options)) {
    m_progressOnTty = ::isatty(STDERR_FILENO) != 0;
    m_deadline.setSingleShot(true);
}

CliRunner::~CliRunner() {
    m_session.reset(); // the session refers to the link: it goes first
    m_link.reset();
}

void CliRunner::start() {
    for (const CliCommand& c : m_options.commands) {
        if (!needsDrive(c)) continue;
        return connectDrive();
    }
    next();
}

void CliRunner::connectDrive() {
    if (m_options.drive != QLatin1String("bds5")) {
        const bool known = drive_core::familyFromName(m_options.drive.toStdString()).has_value();
        return fail(kUsage, known ? QStringLiteral("the %1 is not supported yet; only bds5 is").arg(m_options.drive)
                                  : QStringLiteral("unknown drive \"%1\"").arg(m_options.drive));
    }
    if (m_options.simulated) {
        // A record's trigger (--then "J 1000") goes out when the drive has accepted RECORD, a host round trip
        // later: at 20 times real time a 10 ms hiccup of a busy machine is 200 ms of drive time, a whole
        // recording missed. With a trigger the drive runs in real time, as a real one would.
        const bool triggered = std::any_of(m_options.commands.begin(), m_options.commands.end(),
                                           [](const CliCommand& c) { return !c.recordThen.isEmpty(); });
        m_speed = triggered ? 1.0 : kSimulatorSpeed;
        m_link = std::make_unique<serialport::SimulatorLink>(
            drive_core::DriveFamily::Bds5, serialport::SimulatorLink::Options{m_speed, 9600, false});
    } else {
        m_link = std::make_unique<serialport::SerialPortLink>(m_options.port, m_options.baud);
    }
    m_session = std::make_unique<Bds5Session>(*m_link);
    connect(m_link.get(), &serialport::Link::errorOccurred, this, [this](const QString& why) { fail(kNoAnswer, why); });
    connect(m_session.get(), &Bds5Session::stateChanged, this, [this](Bds5Session::State s) {
        if (s == Bds5Session::State::Ready && m_next == 0 && m_deadline.isActive()) {
            m_deadline.stop();
            next();
        }
    });
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        if (m_following) return;
        fail(kNoAnswer, QStringLiteral("no answer from the drive on %1 (no --> prompt within %2 s)")
                            .arg(m_link->description())
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
    case CliCommand::Kind::Compile:
        return fail(kUsage, QStringLiteral("compile: the SC750 compiler is not available yet"));
    case CliCommand::Kind::Download:
    case CliCommand::Kind::Upload:
    case CliCommand::Kind::VarsDump:
    case CliCommand::Kind::VarsSend: return transfer(c);
    case CliCommand::Kind::Send: return sendLines(c.args, 0);
    case CliCommand::Kind::Run: return run(c);
    case CliCommand::Kind::Stop: return stop();
    case CliCommand::Kind::Record: return record(c);
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

// check FILE: the editor's diagnostics, FILE:LINE:COL: error: message (exit 1 if any).
void CliRunner::check(const CliCommand& c) {
    QString error;
    const auto text = readFile(c.args[0], error);
    if (!text) return fail(kUsage, error);
    std::vector<std::string> lines;
    for (QString line : text->split(QLatin1Char('\n'))) {
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
        lines.push_back(line.toStdString());
    }
    if (!lines.empty() && lines.back().empty()) lines.pop_back();
    const auto diagnostics = drive_core::bds5::checkProgram(lines);
    for (const auto& d : diagnostics) {
        const QString what = d.code ? QStringLiteral("ERR %1 '%2' %3")
                                          .arg(d.code)
                                          .arg(QString::fromStdString(d.entry), QString::fromStdString(d.message))
                                    : QString::fromStdString(d.message);
        out(QStringLiteral("%1:%2:%3: error: %4\n").arg(c.args[0]).arg(d.line).arg(d.column + 1).arg(what));
    }
    if (!diagnostics.empty())
        return fail(kDriveError, QStringLiteral("%1: %2 diagnostic(s)").arg(c.args[0]).arg(diagnostics.size()));
    next();
}

void CliRunner::transfer(const CliCommand& c) {
    serialport::Bds5Transfer* t = nullptr;
    QString error;
    if (c.kind == CliCommand::Kind::Download || c.kind == CliCommand::Kind::VarsSend) {
        const auto text = readFile(c.args[0], error);
        if (!text) return fail(kUsage, error);
        if (c.kind == CliCommand::Kind::Download)
            t = new serialport::Bds5Download(*m_session, *text, {}, this);
        else
            t = new serialport::Bds5VariablesToDrive(*m_session, *text, this);
    } else if (c.kind == CliCommand::Kind::Upload) {
        t = new serialport::Bds5Upload(*m_session, this);
    } else {
        t = new serialport::Bds5VariablesFromDrive(*m_session, this);
    }
    watchTransfer(t, c);
    t->start();
}

void CliRunner::watchTransfer(serialport::Bds5Transfer* t, const CliCommand& c) {
    connect(t, &serialport::Bds5Transfer::progress, this, [this](int done, int total) {
        progress(total > 0 ? QStringLiteral("%1/%2 lines").arg(done).arg(total) : QStringLiteral("%1 lines").arg(done));
    });
    connect(t, &serialport::Bds5Transfer::finished, this, [this, t, c](const serialport::Bds5TransferResult& r) {
        progress(QString());
        t->deleteLater();
        transferDone(c, r);
    });
}

void CliRunner::transferDone(const CliCommand& c, const serialport::Bds5TransferResult& r) {
    for (const auto& e : r.errors)
        out(QStringLiteral("%1:%2: ERR %3 '%4' %5\n")
                .arg(c.args.value(0))
                .arg(e.sourceLine)
                .arg(e.error.code)
                .arg(e.error.entry, e.error.message));
    if (!r.ok()) return fail(kDriveError, r.summary);
    QString error;
    if (c.kind == CliCommand::Kind::Upload &&
        !writeFile(c.args[0], r.lines.join(QLatin1Char('\n')) + QLatin1Char('\n'), error))
        return fail(kUsage, error);
    if (c.kind == CliCommand::Kind::VarsDump &&
        !writeFile(c.args[0], r.lines.join(QLatin1Char('\n')) + QLatin1Char('\n'), error))
        return fail(kUsage, error);
    if (!r.errors.isEmpty()) return fail(kDriveError, r.summary);
    out(r.summary + QLatin1Char('\n'));
    next();
}

// send LINE...: each line at its prompt; the drive's answer lines on stdout; a drive error stops the run.
void CliRunner::sendLines(const QStringList& lines, int index) {
    if (index >= lines.size()) return next();
    const quint64 id = m_session->send(lines[index]);
    auto* guard = new QObject(this);
    connect(m_session.get(), &Bds5Session::finished, guard,
            [this, guard, id, lines, index](quint64 done, const serialport::Bds5Response& r) {
                if (done != id) return;
                guard->deleteLater();
                for (const QString& l : r.lines) out(l + QLatin1Char('\n'));
                for (const auto& e : r.errors)
                    out(QStringLiteral("ERR %1 '%2' %3\n").arg(e.code).arg(e.entry, e.message));
                if (!r.errors.isEmpty())
                    return fail(kDriveError, QStringLiteral("the drive refused \"%1\": ERR %2 %3")
                                                 .arg(lines[index])
                                                 .arg(r.errors.first().code)
                                                 .arg(r.errors.first().message));
                sendLines(lines, index + 1);
            });
    connect(m_session.get(), &Bds5Session::failed, guard, [this, guard, id](quint64 done, const QString& why) {
        if (done != id) return;
        guard->deleteLater();
        fail(kNoAnswer, why);
    });
}

// run [LABEL] [--follow S]: RUN gives no prompt while the program runs; with --follow the program's output
// is printed until the --> prompt comes back (it ended) or S seconds of drive time have passed.
void CliRunner::run(const CliCommand& c) {
    const QByteArray line = (c.args.isEmpty() ? QByteArray("RUN") : "RUN " + c.args[0].toLatin1());
    m_raw.clear();
    auto* guard = new QObject(this);
    const bool follow = c.followSeconds > 0;
    connect(m_session.get(), &Bds5Session::rawReceived, guard, [this, guard, line, follow](const QByteArray& b) {
        m_raw += b;
        const QByteArray echo = line + "\r\n";
        if (!m_raw.startsWith(echo)) {
            if (m_raw.size() >= echo.size() || !echo.startsWith(m_raw)) { // an error instead of the echo
                if (m_raw.contains("\r\n-->") || m_raw.contains("ERR")) {
                    guard->deleteLater();
                    out(QString::fromLatin1(m_raw).remove(QLatin1Char('\r')));
                    return fail(kDriveError, QStringLiteral("the drive refused \"%1\"").arg(QString::fromLatin1(line)));
                }
            }
            return;
        }
        const QByteArray body = m_raw.mid(echo.size());
        if (!follow) {
            guard->deleteLater();
            return next();
        }
        if (body.contains("ERR ") && body.endsWith("-->")) {
            guard->deleteLater();
            out(QString::fromLatin1(body.left(body.size() - 3)).remove(QLatin1Char('\r')));
            return fail(kDriveError, QStringLiteral("the program stopped with a drive error"));
        }
        if (body.endsWith("\r\n-->") || body == "-->") { // the program ended: back at the prompt
            guard->deleteLater();
            m_deadline.stop();
            m_following = false;
            out(QString::fromLatin1(body.left(body.size() - 3)).remove(QLatin1Char('\r')));
            return next();
        }
    });
    if (follow) {
        m_following = true;
        connect(&m_deadline, &QTimer::timeout, guard, [this, guard] {
            guard->deleteLater();
            m_following = false;
            const QByteArray body = m_raw.mid(m_raw.indexOf("\r\n") + 2);
            out(QString::fromLatin1(body).remove(QLatin1Char('\r')));
            next();
        });
        m_deadline.start(int(c.followSeconds * 1000 / m_speed));
    }
    m_session->sendRaw(line + '\r');
}

// stop: ^X at once, ahead of anything queued; the drive answers with its prompt.
void CliRunner::stop() {
    auto* guard = new QObject(this);
    connect(m_session.get(), &Bds5Session::stateChanged, guard, [this, guard](Bds5Session::State s) {
        if (s != Bds5Session::State::Ready) return;
        guard->deleteLater();
        next();
    });
    QTimer::singleShot(2000, guard, [this, guard] { // ^X at the --> prompt changes nothing visible
        guard->deleteLater();
        next();
    });
    m_session->sendUrgent("\x18");
}

} // namespace app::cli

namespace app::cli {

// record: RECORD n t vars, the optional trigger, wait n*t ms of drive time, then PLAY into the scope's CSV.
void CliRunner::record(const CliCommand& c) {
    QStringList lines{QStringLiteral("RECORD %1 %2 %3")
                          .arg(c.recordCount)
                          .arg(c.recordIntervalMs)
                          .arg(c.recordVariables.join(QLatin1Char(' ')))};
    if (!c.recordThen.isEmpty()) lines << c.recordThen;
    auto* guard = new QObject(this);
    auto left = std::make_shared<int>(int(lines.size())); // answers still to come
    connect(m_session.get(), &Bds5Session::finished, guard,
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
    connect(m_session.get(), &Bds5Session::failed, guard, [this, guard](quint64, const QString& why) {
        guard->deleteLater();
        fail(kNoAnswer, why);
    });
    for (const QString& l : lines) m_session->send(l);
}

// PLAY's first line repeats the set-up, then one line per sample, 12 columns a value (the drive's choice,
// documented in drive_core/bds5/bds5_recorder.h). The CSV names variables, units and interval.
void CliRunner::play(const CliCommand& c) {
    const quint64 id = m_session->send(QStringLiteral("PLAY"));
    auto* guard = new QObject(this);
    connect(
        m_session.get(), &Bds5Session::finished, guard,
        [this, guard, id, c](quint64 done, const serialport::Bds5Response& r) {
            if (done != id) return;
            guard->deleteLater();
            progress(QString());
            if (!r.errors.isEmpty())
                return fail(kDriveError,
                            QStringLiteral("PLAY: ERR %1 %2").arg(r.errors.first().code).arg(r.errors.first().message));
            QString csv = QStringLiteral("# ServoDesk RECORD %1 samples every %2 ms\n")
                              .arg(c.recordCount)
                              .arg(c.recordIntervalMs);
            csv += QStringLiteral("time_s");
            for (const QString& v : c.recordVariables) {
                const auto ref = drive_core::catalog::bds5::findVariable(v.toStdString());
                const QString unit =
                    ref ? QString::fromLatin1(ref->info->units.data(), qsizetype(ref->info->units.size())) : QString();
                csv += QStringLiteral(",%1 [%2]").arg(v, unit);
            }
            csv += QLatin1Char('\n');
            int samples = 0;
            for (int i = 1; i < r.lines.size(); ++i) { // line 0 repeats the RECORD set-up
                const QStringList values = r.lines[i].split(QLatin1Char(' '), Qt::SkipEmptyParts);
                if (values.size() != c.recordVariables.size()) continue;
                csv += QString::number(double(samples) * c.recordIntervalMs / 1000.0, 'f', 3);
                for (const QString& v : values) csv += QLatin1Char(',') + v;
                csv += QLatin1Char('\n');
                ++samples;
            }
            if (samples == 0) return fail(kDriveError, QStringLiteral("PLAY returned no samples"));
            QString error;
            if (!writeFile(c.csvPath, csv, error)) return fail(kUsage, error);
            out(QStringLiteral("%1 samples of %2 written to %3\n")
                    .arg(samples)
                    .arg(c.recordVariables.join(QLatin1Char(',')))
                    .arg(c.csvPath));
            next();
        });
}

} // namespace app::cli
