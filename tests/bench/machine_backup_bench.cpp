// How long a machine backup of 8 BDS5 axes takes against what its bytes need on the wire (issue 21, goal
// <= 1.15): MachineJob over a SimulatorLink carrying a MultidropBus of axes A-H at 9600 baud with the line rate
// on, each axis holding a program, timed in the drive's own time (the link's drive clock) so a loaded host does
// not change the figure. The limit is every byte the backup moved (selections, commands, echoes, listings; 10
// bits each) at the baud rate, both ways on one pair as a 2-wire RS-485 multidrop line carries them. Prints
// figures; asserts nothing about time. Run: build/tests/bench/machine_backup_bench
#include "machine/machine_job.h"
#include "serialport/axis_link.h"
#include "serialport/drive_session.h"
#include "serialport/simulator_link.h"

#include <QCoreApplication>
#include <QTemporaryDir>

#include <cstdio>
#include <memory>

namespace {
constexpr int kAxes = 8;
// Each axis's program: the manual's first session (L3427-3462) grown to a few dozen lines.
QString program() {
    QString text = QStringLiteral("10$\n");
    for (int i = 1; i <= 30; ++i) text += QStringLiteral("X%1=%2\n").arg(i).arg(i * 7);
    return text + QStringLiteral("P \"HELLO WORLD\"\nB\n");
}
} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    serialport::SimulatorLink::Options options;
    options.speedFactor = 1; // real time: at any speed up the host's turnaround would count as drive time
    app::machine::MachineProject project;
    for (int i = 0; i < kAxes; ++i) {
        options.axes.emplace_back(1, char('A' + i));
        project.axes.append(app::machine::MachineProject::axisNamed(QString(QChar('A' + i)), drive_core::DriveFamily::Bds5));
    }
    serialport::SimulatorLink line(drive_core::DriveFamily::Bds5, options);
    QTemporaryDir dir;
    std::unique_ptr<app::machine::MachineJob> job;
    double startMs = 0;
    int loaded = 0;
    std::unique_ptr<serialport::AxisLink> axis;
    std::unique_ptr<serialport::DriveSession> session;
    // First each axis gets its program (not timed), then the backup.
    std::function<void()> loadNext = [&] {
        session.reset();
        axis.reset();
        if (loaded == kAxes) {
            job = std::make_unique<app::machine::MachineJob>(app::machine::MachineJob::Kind::Backup, line, project,
                                                             dir.path());
            QObject::connect(job.get(), &app::machine::MachineJob::finished, [&](bool ok, const QString& summary) {
                const double tookMs = line.driveClockMs().value_or(0) - startMs;
                const qint64 bytes = job->bytesSent() + job->bytesReceived();
                const double limitMs = double(bytes) * 10.0 * 1000.0 / line.baudRate();
                std::printf("machine backup: %s\n", qPrintable(summary));
                std::printf("machine backup: %d axes in %.0f ms of drive time; its %lld bytes (%lld sent, %lld "
                            "received) need %.0f ms at %d baud\n",
                            kAxes, tookMs, qlonglong(bytes), qlonglong(job->bytesSent()), qlonglong(job->bytesReceived()),
                            limitMs, line.baudRate());
                std::printf("machine backup: %.2fx the line-rate limit (goal <= 1.15)\n", tookMs / limitMs);
                app.exit(ok ? 0 : 1);
            });
            startMs = line.driveClockMs().value_or(0);
            job->start();
            return;
        }
        axis = std::make_unique<serialport::AxisLink>(line, drive_core::DriveFamily::Bds5, QString(QChar('A' + loaded)));
        session = serialport::makeDriveSession(drive_core::DriveFamily::Bds5, *axis);
        auto sent = std::make_shared<bool>(false);
        QObject::connect(session.get(), &serialport::DriveSession::readyChanged, [&, sent](bool ready) {
            if (ready && !*sent) session->download(program());
            *sent = *sent || ready;
        });
        QObject::connect(session.get(), &serialport::DriveSession::transferFinished,
                         [&](const serialport::TransferResult& r) {
                             if (!r.ok()) {
                                 std::fprintf(stderr, "machine backup: loading axis %c: %s\n", 'A' + loaded,
                                              qPrintable(r.message));
                                 return app.exit(1);
                             }
                             ++loaded;
                             QMetaObject::invokeMethod(&app, loadNext, Qt::QueuedConnection);
                         });
        axis->open();
    };
    QObject::connect(&line, &serialport::Link::errorOccurred, [&](const QString& why) {
        std::fprintf(stderr, "machine backup: %s\n", qPrintable(why));
        app.exit(1);
    });
    loadNext();
    const int code = app.exec();
    job.reset();
    session.reset();
    axis.reset();
    return code;
}
