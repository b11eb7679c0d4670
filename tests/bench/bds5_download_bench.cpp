// How fast Bds5Download sends a 2,000-line program to the simulated BDS5: over the in-process link (no wire,
// goal < 0.2 s) and over the drive's 9600-baud UART, against the line-rate limit. Prints figures; asserts
// nothing about time. Run: build/tests/bench/bds5_download_bench
#include "serialport/bds5_download.h"
#include "serialport/bds5_session.h"
#include "serialport/simulator_link.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <cstdio>

namespace {

constexpr int kLines = 2000;
constexpr int kBaud = 9600;

// 2,000 short lines (the drive holds ~16,000 characters: about 8 a line, CR included): assignments, with a
// label and a print now and then, as a long table-driven program would look.
QString program() {
    QString text;
    for (int i = 0; i < kLines; ++i) {
        if (i % 100 == 0)
            text += QStringLiteral("%1$\n").arg(i / 100 + 1);
        else if (i % 100 == 99)
            text += QStringLiteral("P X%1\n").arg(i % 90 + 1);
        else
            text += QStringLiteral("X%1=%2\n").arg(i % 90 + 1).arg(i % 10);
    }
    return text;
}

struct WireCount {
    long hostToDrive = 0; // lines + CR, ">BDS" + CR, Esc
    long driveToHost = 0; // echo, CR LF, prompts
    long total() const { return hostToDrive + driveToHost; }
};

// Every character that crosses the wire for a download: ">BDS<cr>" echoed with "<cr><lf>l->", each line +
// CR echoed with CR LF and "l->", Esc answered with "<cr><lf>-->".
WireCount wireCharacters(const serialport::Bds5ProgramText& p) {
    WireCount c;
    c.hostToDrive += 5;
    c.driveToHost += 4 + 2 + 3;
    for (const QString& line : p.lines()) {
        c.hostToDrive += line.size() + 1;
        c.driveToHost += line.size() + 2 + 3;
    }
    c.hostToDrive += 1;
    c.driveToHost += 2 + 3;
    return c;
}

struct Run {
    double seconds = -1;
    serialport::Bds5TransferResult result;
};

Run download(bool paced) {
    serialport::SimulatorLink link(drive_core::DriveFamily::Bds5, {1.0, kBaud, paced});
    serialport::Bds5Session session(link);
    serialport::Bds5Download transfer(session, program(), {QString(), false, false});
    Run run;
    QElapsedTimer timer;
    QObject::connect(&transfer, &serialport::Bds5Transfer::finished,
                     [&](const serialport::Bds5TransferResult& r) {
                         run.seconds = double(timer.nsecsElapsed()) / 1e9;
                         run.result = r;
                         QCoreApplication::exit(0);
                     });
    QObject::connect(&session, &serialport::Bds5Session::stateChanged, [&](auto state) {
        if (state == serialport::Bds5Session::State::Ready && !timer.isValid()) {
            timer.start();
            transfer.start();
        }
    });
    QTimer::singleShot(300'000, [] { QCoreApplication::exit(1); });
    link.open();
    QCoreApplication::exec();
    return run;
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const auto text = serialport::Bds5ProgramText::prepare(program(), false);
    const WireCount wire = wireCharacters(text);
    std::printf("program: %d lines, %d characters with CRs\n", text.lineCount(), text.charactersSent());

    const Run fast = download(false);
    if (fast.seconds < 0 || !fast.result.ok()) {
        std::printf("in-process: FAILED: %s\n", qPrintable(fast.result.summary));
        return 1;
    }
    std::printf("in-process link (no wire): %d lines in %.3f s = %.0f lines/s (goal < 0.2 s)\n",
                fast.result.linesDone, fast.seconds, fast.result.linesDone / fast.seconds);

    const Run paced = download(true);
    if (paced.seconds < 0 || !paced.result.ok()) {
        std::printf("9600 baud: FAILED: %s\n", qPrintable(paced.result.summary));
        return 1;
    }
    const double limit = double(wire.total()) * 10.0 / kBaud;
    const double oneWay = double(wire.driveToHost) * 10.0 / kBaud;
    std::printf(
        "%d-baud link: %d lines in %.2f s; line-rate limit %.2f s (%ld characters both ways x 10 bits / "
        "%d): ratio %.2f (goal <= 1.10)\n",
        kBaud, paced.result.linesDone, paced.seconds, limit, wire.total(), kBaud, paced.seconds / limit);
    std::printf(
        "  (the simulated UART paces only what the drive sends: %ld characters = %.2f s, ratio %.2f to "
        "that one-way limit)\n",
        wire.driveToHost, oneWay, paced.seconds / oneWay);
    return 0;
}
