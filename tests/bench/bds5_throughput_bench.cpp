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

void feed(drive_core::bds5::Bds5Drive& drive, std::string_view bytes) {
    drive.receive(bytes);
    for (int i = 0; i < 100 || drive.transmitting(); ++i) drive.step(std::chrono::milliseconds(1));
    drive.takeTransmitted();
}

// A running program (a counting loop with a print every 100 passes) in simulated time: how many simulated
// seconds the engine covers per wall-clock second — the simulator's margin over real time.
void benchEngine() {
    drive_core::bds5::Bds5Drive drive;
    drive.powerUp();
    feed(drive, ">BDS\r");
    for (const char* line : {"1$", "X1=X1+1", "? X1/100*100 EQ X1 P X1", "GOTO 1"}) {
        feed(drive, line);
        feed(drive, "\r");
    }
    feed(drive, "\x1bRUN 1\r");
    constexpr int kSimulatedMs = 60'000;
    QElapsedTimer timer;
    timer.start();
    std::size_t bytes = 0;
    for (int i = 0; i < kSimulatedMs; ++i) {
        drive.step(std::chrono::milliseconds(1));
        bytes += drive.takeTransmitted().size();
    }
    const double wall = double(timer.nsecsElapsed()) / 1e9;
    std::printf("engine: %d s of a running program simulated in %.3f s wall = %.0fx real time (%zu bytes sent)\n",
                kSimulatedMs / 1000, wall, kSimulatedMs / 1000.0 / wall, bytes);
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
    return 0;
}
