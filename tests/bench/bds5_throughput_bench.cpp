// How fast the simulated BDS5 and Bds5Session go, against the physical limit of the 9600-baud wire.
// Prints figures; asserts nothing about time. Run: build/tests/bench/bds5_throughput_bench
#include "drive_core/bds5/bds5_drive.h"
#include "serialport/bds5_session.h"
#include "serialport/simulator_link.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <chrono>
#include <cstdio>

namespace {

// Each command crosses the wire twice (echo) and brings back a 12-column value: 10 bits a character.
double wireSecondsPerCommand(const QByteArray& command, int answerChars, int baud) {
    const int chars = int(command.size()) + 1 /*CR*/ + 2 /*CR LF*/ + answerChars + 3 /*prompt*/;
    return chars * 10.0 / baud;
}

void benchEngine() {
    drive_core::bds5::Bds5Drive drive;
    drive.powerUp();
    drive.takeTransmitted();
    constexpr int kCommands = 200'000;
    QElapsedTimer timer;
    timer.start();
    std::size_t bytes = 0;
    for (int i = 0; i < kCommands; ++i) {
        drive.receive("X1=X1+1\rP X1*2[H] \"OK\"\r");
        drive.step(std::chrono::milliseconds(1));
        bytes += drive.takeTransmitted().size();
    }
    const double s = double(timer.nsecsElapsed()) / 1e9;
    const double perSecond = 2.0 * kCommands / s;
    const double wireLimit = 1.0 / wireSecondsPerCommand("P X1*2[H] \"OK\"", 11, 19200);
    std::printf("engine: %.0f instructions/s (%.1f MB/s out); %.0fx the 19200-baud wire's %.0f instructions/s\n",
                perSecond, double(bytes) / s / 1e6, perSecond / wireLimit, wireLimit);
}

void benchSession(int baud) {
    serialport::SimulatorLink link(drive_core::DriveFamily::Bds5, {1.0, baud});
    serialport::Bds5Session session(link);
    constexpr int kCommands = 60;
    int done = 0;
    QElapsedTimer timer;
    QObject::connect(&session, &serialport::Bds5Session::finished, [&] {
        if (++done == kCommands) QCoreApplication::exit(0);
    });
    QObject::connect(&session, &serialport::Bds5Session::stateChanged, [&](auto state) {
        if (state == serialport::Bds5Session::State::Ready && !timer.isValid()) {
            timer.start();
            for (int i = 0; i < kCommands; ++i) session.send(QStringLiteral("P X1"));
        }
    });
    QTimer::singleShot(60'000, [] { QCoreApplication::exit(1); });
    link.open();
    if (QCoreApplication::exec() != 0) {
        std::printf("session @%d baud: timed out after %d commands\n", baud, done);
        return;
    }
    const double s = double(timer.nsecsElapsed()) / 1e9;
    const double limit = 1.0 / wireSecondsPerCommand("P X1", 12, baud);
    std::printf("session @%d baud: %.1f commands/s, wire limit %.1f/s, ratio %.2f (prompt silence %d ms)\n", baud,
                kCommands / s, limit, kCommands / s / limit, link.quietMs());
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    benchEngine();
    benchSession(9600);
    benchSession(19200);
    return 0;
}
