// servodesk-cli machine scan, backup, compare and restore: the axes of a multidrop line (issue 21).
#include "cli_runner.h"

#include "machine/axis_scan.h"
#include "machine/machine_job.h"
#include "serialport/axis_link.h"
#include "serialport/link.h"
#include "serialport/port_link.h"

#include <QElapsedTimer>

namespace app::cli {

using machine::AxisReport;
using machine::CompareRow;
using machine::MachineJob;
using machine::MachineProject;

bool isMachineCommand(const CliCommand& c) {
    switch (c.kind) {
    case CliCommand::Kind::MachineScan:
    case CliCommand::Kind::MachineBackup:
    case CliCommand::Kind::MachineCompare:
    case CliCommand::Kind::MachineRestore: return true;
    default: return false;
    }
}

namespace {
// "A,B,C" or "ABC" (one-character IDs) into IDs.
QStringList idList(const QString& text) {
    if (text.contains(u',')) return text.split(u',', Qt::SkipEmptyParts);
    QStringList ids;
    for (const QChar c : text) ids << QString(c);
    return ids;
}
} // namespace

// Alone on its connection: a machine command selects axis after axis on the line, and leaves none selected.
void CliRunner::machine(const CliCommand& c) {
    if (m_options.commands.size() != 1)
        return fail(kUsage, QStringLiteral("a machine command runs alone: give it its own servodesk-cli call"));
    if (!m_options.axis.isEmpty())
        return fail(kUsage, QStringLiteral("a machine command reaches every axis itself: leave out --axis"));
    if (c.kind == CliCommand::Kind::MachineScan) return machineScan(c);
    machineJob(c);
}

// Alone on its connection: a line of sleeping axes never makes a session ready, and the scan leaves every axis
// asleep again.
void CliRunner::machineScan(const CliCommand& c) {
    if (m_options.simulated)
        return fail(kUsage, QStringLiteral("machine scan needs --port: a multidrop line (servodesk-sim --axes serves "
                                           "one)"));
    const QStringList ids = c.scanIds.isEmpty() ? serialport::allAxisIds(m_family) : idList(c.scanIds);
    for (const QString& id : ids)
        if (const QString problem = serialport::axisIdProblem(m_family, id); !problem.isEmpty())
            return fail(kUsage, QStringLiteral("machine scan --ids: %1").arg(problem));
    m_link = serialport::makePortLink(m_options.port, m_options.baud, m_family);
    auto* scan = new machine::AxisScan(*m_link, m_family, ids, c.scanWaitMs, this);
    auto* clock = new QElapsedTimer;
    connect(m_link.get(), &serialport::Link::errorOccurred, this, [this](const QString& why) { fail(kNoAnswer, why); });
    connect(m_link.get(), &serialport::Link::opened, this, [scan, clock] {
        clock->start();
        scan->start();
    });
    connect(scan, &machine::AxisScan::progress, this, [this, ids](int called, int total) {
        progress(QStringLiteral("calling axis %1 (%2 of %3)").arg(ids.at(called)).arg(called + 1).arg(total));
    });
    connect(scan, &machine::AxisScan::finished, this, [this, clock, ids](const QList<machine::FoundAxis>& axes) {
        progress(QString());
        for (const auto& a : axes) out(QStringLiteral("%1 %2 %3\n").arg(a.id, familyDisplayName(a.family), a.answer));
        std::fprintf(stderr, "machine scan: %lld axes answered of %lld IDs called, in %.2f s on %s\n",
                     qlonglong(axes.size()), qlonglong(ids.size()), clock->elapsed() / 1000.0,
                     qPrintable(m_link->description()));
        delete clock;
        if (axes.isEmpty()) return fail(kNoAnswer, QStringLiteral("no axis answered on %1").arg(m_link->description()));
        emit done(kOk);
    });
    m_link->open();
}

} // namespace app::cli

namespace app::cli {

namespace {
QString rowText(const AxisReport& r, const CompareRow& row, const QString& right) {
    if (row.kind == CompareRow::Kind::Variable)
        return QStringLiteral("%1 variable %2: file %3, %4 %5\n")
            .arg(r.id, row.key, row.left.isEmpty() ? QStringLiteral("(none)") : row.left, right,
                 row.right.isEmpty() ? QStringLiteral("(none)") : row.right);
    const QString where = row.leftLine > 0 ? QStringLiteral("line %1").arg(row.leftLine)
                                           : QStringLiteral("%1 line %2").arg(right).arg(row.rightLine);
    return QStringLiteral("%1 program %2: file \"%3\", %4 \"%5\"\n").arg(r.id, where, row.left, right, row.right);
}
} // namespace

// machine backup DIR | compare DIR | restore DIR: one MachineJob over the line; one line per axis on stdout
// ("B done read 12 program lines and its variables"), and for compare each differing row under it.
void CliRunner::machineJob(const CliCommand& c) {
    const QString dir = c.args.value(0);
    MachineProject project;
    if (c.kind == CliCommand::Kind::MachineBackup) {
        if (m_options.simulated)
            return fail(kUsage, QStringLiteral("machine backup needs --port: the line the axes are on"));
        project.port = m_options.port;
        project.baud = m_options.baud;
        for (const QString& id : idList(c.scanIds)) {
            if (const QString problem = serialport::axisIdProblem(m_family, id); !problem.isEmpty())
                return fail(kUsage, QStringLiteral("machine backup --ids: %1").arg(problem));
            project.axes.append(MachineProject::axisNamed(id, m_family));
        }
    } else {
        QString error;
        const auto read = machine::readMachineProject(dir, error);
        if (!read) return fail(kUsage, error);
        project = *read;
        if (m_options.simulated) { // the project's own line
            m_options.port = project.port;
            m_options.baud = project.baud;
            if (project.port.isEmpty())
                return fail(kUsage, QStringLiteral("%1 names no port: give --port").arg(MachineProject::fileName()));
        }
        m_family = project.family();
    }
    m_link = serialport::makePortLink(m_options.port, m_options.baud, m_family);
    connect(m_link.get(), &serialport::Link::errorOccurred, this, [this](const QString& why) { fail(kNoAnswer, why); });
    const auto run = [this, c, dir](MachineProject p) {
        const auto kind = c.kind == CliCommand::Kind::MachineBackup    ? MachineJob::Kind::Backup
                          : c.kind == CliCommand::Kind::MachineCompare ? MachineJob::Kind::Compare
                                                                       : MachineJob::Kind::Restore;
        auto* job = new MachineJob(kind, *m_link, std::move(p), dir, this);
        auto* clock = new QElapsedTimer;
        clock->start();
        connect(job, &MachineJob::stageChanged, this, [this](const QString& s) { progress(s); });
        connect(job, &MachineJob::axisFinished, this, [this, kind](const AxisReport& r) {
            progress(QString());
            QString line = QStringLiteral("%1 %2 %3").arg(r.id, machine::outcomeWord(r.outcome), r.message);
            if (kind == MachineJob::Kind::Restore) line += QStringLiteral(" (the drive holds %1)").arg(r.driveHolds);
            out(line + QLatin1Char('\n'));
            for (const CompareRow& row : machine::differences(r.rows))
                out(rowText(r, row, kind == MachineJob::Kind::Compare ? QStringLiteral("drive")
                                                                      : QStringLiteral("read back")));
        });
        connect(job, &MachineJob::finished, this, [this, job, clock](bool ok, const QString& summary) {
            std::fprintf(stderr, "machine: %s (%.2f s, %lld bytes sent and %lld received on %s)\n", qPrintable(summary),
                         clock->elapsed() / 1000.0, qlonglong(job->bytesSent()), qlonglong(job->bytesReceived()),
                         qPrintable(m_link->description()));
            delete clock;
            if (!ok) return fail(kDriveError, summary);
            emit done(kOk);
        });
        job->start();
    };
    if (!project.axes.isEmpty()) {
        connect(m_link.get(), &serialport::Link::opened, this, [run, project] { run(project); });
        return m_link->open();
    }
    // A backup without --ids: the axes a scan of every ID finds.
    const QStringList ids = serialport::allAxisIds(m_family);
    auto* scan = new machine::AxisScan(*m_link, m_family, ids, c.scanWaitMs, this);
    connect(m_link.get(), &serialport::Link::opened, scan, &machine::AxisScan::start);
    connect(scan, &machine::AxisScan::progress, this, [this](int called, int total) {
        progress(QStringLiteral("scanning: %1 of %2 IDs called").arg(called + 1).arg(total));
    });
    connect(scan, &machine::AxisScan::finished, this, [this, run, project](const QList<machine::FoundAxis>& axes) mutable {
        progress(QString());
        if (axes.isEmpty()) return fail(kNoAnswer, QStringLiteral("no axis answered on %1").arg(m_link->description()));
        for (const auto& a : axes) project.axes.append(MachineProject::axisNamed(a.id, m_family));
        run(project);
    });
    m_link->open();
}

} // namespace app::cli
