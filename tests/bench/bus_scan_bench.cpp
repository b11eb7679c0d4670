// How long a scan of a 32-axis BDS5 multidrop line takes against what its bytes need on the wire (issue 21):
// Bds5BusScan over a SimulatorLink carrying a MultidropBus of axes 0-9 and A-V, at 9600 baud with the line
// rate on, timed in the drive's own time (the link's drive clock), so a loaded host does not change the
// figure. The limit is the scan's bytes (the calls and the answers, 10 bits each) at the baud rate; the
// four IDs no axis answers (W-Z) each cost the scan's wait on top. Prints figures; asserts nothing about time.
// Run: build/tests/bench/bus_scan_bench
#include "serialport/bds5_bus_scan.h"
#include "serialport/simulator_link.h"

#include <QCoreApplication>

#include <cstdio>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    serialport::SimulatorLink::Options options;
    options.speedFactor = 1; // real time: at any speed up the host's turnaround between calls would count as drive time
    for (char c = '0'; c <= '9'; ++c) options.axes.emplace_back(1, c);
    for (char c = 'A'; c <= 'V'; ++c) options.axes.emplace_back(1, c);
    serialport::SimulatorLink link(drive_core::DriveFamily::Bds5, options);
    constexpr int kWaitMs = 100;
    serialport::Bds5BusScan scan(link, serialport::Bds5BusScan::allIds(), kWaitMs);
    qint64 sent = 0, received = 0;
    double startMs = 0;
    QObject::connect(&link, &serialport::Link::bytesReceived, [&received](const QByteArray& b) { received += b.size(); });
    QObject::connect(&link, &serialport::Link::opened, [&] {
        startMs = link.driveClockMs().value_or(0);
        scan.start();
    });
    int exitCode = 0;
    QObject::connect(&scan, &serialport::Bds5BusScan::finished, [&](const QList<serialport::Bds5BusScan::Axis>& axes) {
        const double tookMs = link.driveClockMs().value_or(0) - startMs;
        sent = 2 * serialport::Bds5BusScan::allIds().size(); // '\' and the ID, per ID
        const double limitMs = double(sent + received) * 10.0 * 1000.0 / link.baudRate();
        const double waitsMs = double(serialport::Bds5BusScan::allIds().size() - axes.size()) * kWaitMs;
        std::printf("bus scan: %lld axes found of %lld IDs in %.0f ms of drive time; the scan's %lld bytes need %.0f ms "
                    "at %d baud; %.0f ms are the waits on absent IDs\n",
                    qlonglong(axes.size()), qlonglong(serialport::Bds5BusScan::allIds().size()), tookMs,
                    qlonglong(sent + received), limitMs, link.baudRate(), waitsMs);
        std::printf("bus scan: %.2fx the line-rate limit in all, %.2fx without the waits on absent IDs (32 axes)\n",
                    tookMs / limitMs, (tookMs - waitsMs) / limitMs);
        if (axes.size() != 32) {
            std::fprintf(stderr, "bus scan: expected 32 axes, found %lld\n", qlonglong(axes.size()));
            exitCode = 1;
        }
        app.exit(exitCode);
    });
    QObject::connect(&link, &serialport::Link::errorOccurred, [&](const QString& why) {
        std::fprintf(stderr, "bus scan: %s\n", qPrintable(why));
        app.exit(1);
    });
    link.open();
    return app.exec();
}
