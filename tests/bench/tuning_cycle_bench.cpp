// The tuning loop's cycle against its physical floor (issue 6): the main window's tuning panel on the
// simulated BDS5 at 9600 baud runs the test move continuously; each run's wall time (gains in force, RECORD,
// test move, PLAY, parse, measure, plot) is printed with its ideal — the record's duration plus the PLAY
// listing's bytes on the wire — and their ratio. Goal: ratio <= 1.5. Prints figures; asserts nothing on time.
// Run: build/tests/bench/tuning_cycle_bench
#include "families/bds5/drive_connection.h"
#include "app/main_window.h"
#include "app/scope/scope_controller.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"

#include <QApplication>
#include <QStandardPaths>
#include <QTest>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {
constexpr int kRuns = 4; // a run of 100 ms takes about 8 s: PLAY of 3 channels at 9600 baud
constexpr int kTimeoutMs = 60000;

bool driveReady(const app::MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready &&
           session->mode() == serialport::Bds5Mode::Interactive;
}

void benchMove(app::MainWindow& window, const app::TestMove& move) {
    app::TuningPanel* panel = window.scopeController().tuningPanel();
    app::TuningRunner& runner = panel->runner<app::TuningRunner>();
    app::setTestMove(*panel, move);
    const qsizetype before = runner.runs().size();
    runner.runContinuously();
    const bool done = QTest::qWaitFor([&] { return runner.runs().size() >= before + kRuns; }, kRuns * kTimeoutMs);
    runner.stop();
    if (!QTest::qWaitFor([&] { return !runner.isRunning(); }, kTimeoutMs)) std::printf("  the last run did not end\n");
    if (!done) {
        std::printf("  %s: only %lld runs finished\n", qPrintable(move.description()),
                    static_cast<long long>(runner.runs().size() - before));
        return;
    }
    std::vector<double> ratios;
    double cycle = 0, ideal = 0;
    // The first run of a batch starts from a standstill (no run queued behind it): counted like the others.
    for (qsizetype i = before; i < before + kRuns; ++i) {
        const app::TuningRun& run = runner.runs()[i];
        ratios.push_back(run.cycle_s / run.ideal_s);
        cycle += run.cycle_s / kRuns;
        ideal += run.ideal_s / kRuns;
    }
    std::sort(ratios.begin(), ratios.end());
    std::printf("  %-40s %d runs, cycle %.2f s, ideal %.2f s (record + PLAY bytes), ratio median %.2f, "
                "worst %.2f   goal <= 1.5\n",
                qPrintable(move.description() + QLatin1Char(':')), kRuns, cycle, ideal, ratios[ratios.size() / 2],
                ratios.back());
}
} // namespace

int main(int argc, char** argv) {
    QApplication application(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
    QCoreApplication::setApplicationName(QStringLiteral("ServoDeskTuningCycleBench"));
    app::MainWindow window;
    window.connectDrive(app::ConnectionChoice::simulator()); // 9600 baud, as the drive's own UART
    window.show();
    if (!QTest::qWaitFor([&] { return driveReady(window); }, kTimeoutMs)) {
        std::fprintf(stderr, "the simulated drive did not answer\n");
        return 1;
    }
    app::TuningRunner& runner = window.scopeController().tuningRunner();
    runner.setGain(QStringLiteral("PLIM"), 0); // the factory PMAX/PMIN (+-100 counts) would stop a jog at once
    window.connection().sendCommand(QStringLiteral("EN"));
    if (!QTest::qWaitFor([&] { return driveReady(window); }, kTimeoutMs)) return 1;

    std::printf("tuning_cycle_bench: Run Continuously on the simulated BDS5 at 9600 baud\n");
    app::TestMove step;
    step.amplitude = 500;
    step.durationMs = 50;
    benchMove(window, step);
    app::TestMove position;
    position.kind = app::TestMove::Kind::PositionStep;
    position.amplitude = 2000;
    position.moveVelocity = 1000;
    position.durationMs = 100;
    benchMove(window, position);
    return 0;
}
