// The tuning panel's test-move presets against the simulated BDS5: the amplitude proposed from the drive's
// values keeps ICMD below ILIM (no warning), a deliberately larger step drives ICMD into ILIM and the panel
// warns, the position-step preset moves by its amplitude and back, as the recorded PCMD and PFB show, and the
// amplitude, once proposed, stays while the gains change (issue 19: runs compared one move).
#include "app_test_support.h"
#include "families/bds5/drive_connection.h"
#include "app/main_window.h"
#include "app/scope/scope_controller.h"
#include "app/scope/scope_view.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"

#include "scope/scope_plot.h"

#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

#include <algorithm>
#include <cmath>

using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;
using app_test::driveReady;
constexpr int kIlim = 50; // % of the drive's current (INUM/IDEN at power-up): the proposal follows ILIM

double peakOf(const scope::Capture& capture, const char* channel) {
    const scope::CaptureChannel* c = capture.find(channel);
    if (!c) return -1;
    double peak = 0;
    for (const double v : c->values) peak = std::max(peak, std::abs(v));
    return peak;
}

struct Window {
    MainWindow window;
    app::TuningPanel* panel;
    Window() : panel(window.scopeController().tuningPanel()) {
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
    }
    // Enabled, PLIM off (the factory PMAX/PMIN stop a move at once), ILIM lowered, the values read back.
    bool ready() {
        QSignalSpy values(&panel->runner<app::TuningRunner>(), &app::TuningRunner::driveValuesRead);
        if (!QTest::qWaitFor([this] { return driveReady(window); }, kDriveTimeoutMs)) return false;
        panel->runner<app::TuningRunner>().setGain(QStringLiteral("PLIM"), 0);
        panel->runner<app::TuningRunner>().setGain(QStringLiteral("ILIM"), kIlim);
        window.connection().sendCommand(QStringLiteral("EN"));
        panel->runner<app::TuningRunner>().readGains();
        return values.wait(kDriveTimeoutMs) && QTest::qWaitFor([this] { return driveReady(window); }, kDriveTimeoutMs);
    }
    bool run() {
        QSignalSpy runs(&panel->runner<app::TuningRunner>(), &app::TuningRunner::runFinished);
        panel->runner<app::TuningRunner>().runOnce();
        return runs.wait(kDriveTimeoutMs);
    }
    QSpinBox* amplitudeField() const { return panel->amplitude(); }
};
} // namespace

class TuningPresetsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskTuningPresetsTest"));
    }

    void proposedStepStaysBelowIlimAndALargerOneWarns() {
        Window w;
        QVERIFY(w.ready());
        QCOMPARE(w.panel->runner<app::TuningRunner>().driveValues().value(QStringLiteral("ILIM")), double(kIlim));
        app::TestMove move;
        // The J goes out a host round trip after the drive accepted RECORD: under load (ctest -j 4 beside CPU
        // hogs) that was up to ~95 ms of the record, and a 60 ms step's 120 ms record then ended before ICMD
        // peaked. A 150 ms step leaves 300 ms; the velocity step's proposal does not depend on it.
        move.durationMs = 150;
        app::setTestMove(*w.panel, move);
        w.panel->useProposedAmplitude();
        const int proposed = w.panel->proposedAmplitude();
        QSpinBox* amplitude = w.amplitudeField();
        QVERIFY(amplitude);
        QCOMPARE(amplitude->value(), proposed);
        QCOMPARE(w.panel->runner<app::TuningRunner>().testMove().amplitude, proposed);
        QVERIFY2(amplitude->toolTip().contains(QStringLiteral("jog velocity (J)")), qPrintable(amplitude->toolTip()));
        // Half of ILIM at KV 2000: 0.5 x 0.5 x 2e / (2000 x 5e-6) rad/s = 136 rad/s = 1298 RPM.
        QVERIFY2(proposed > 1000 && proposed < 1500, qPrintable(QString::number(proposed)));

        QVERIFY(w.run());
        const app::TuningRun first = w.panel->runner<app::TuningRunner>().runs().last();
        const double icmd1 = peakOf(first.capture, "ICMD");
        qInfo("proposed J %d: ICMD peaks at %.0f, ILIM %d", proposed, icmd1, kIlim);
        QVERIFY(!first.currentSaturated);
        QVERIFY(w.panel->warningText().isEmpty());
        // Well below ILIM, yet a step that uses the current: not a timid proposal.
        // Below ILIM, yet a step that uses the current: not a timid proposal. (ACC's ramp, 13 ms here, keeps
        // the peak below the formula's worst case of a command faster than the loop.)
        QVERIFY2(icmd1 >= 0.15 * kIlim && icmd1 < 0.9 * kIlim, qPrintable(QString::number(icmd1)));

        // ILIM halved: the proposal halves too, the Amplitude field keeps the move the run was made with.
        QSignalSpy confirmed(&w.panel->runner<app::TuningRunner>(), &app::TuningRunner::gainConfirmed);
        w.panel->runner<app::TuningRunner>().setGain(QStringLiteral("ILIM"), kIlim / 2);
        QVERIFY(confirmed.wait(kDriveTimeoutMs));
        const int halved = w.panel->proposedAmplitude();
        QVERIFY2(std::abs(2 * halved - proposed) <= 1, qPrintable(QString::number(halved)));
        QCOMPARE(amplitude->value(), proposed);
        QVERIFY(w.panel->proposalText().contains(QString::number(halved)));

        // The user types a step eight times that: ICMD reaches ILIM and the panel says so.
        amplitude->setValue(8 * halved);
        QCOMPARE(w.panel->runner<app::TuningRunner>().testMove().amplitude, 8 * halved);
        QVERIFY(w.run());
        const app::TuningRun second = w.panel->runner<app::TuningRunner>().runs().last();
        qInfo("J %d at ILIM %d: ICMD peaks at %.0f", 8 * halved, kIlim / 2, peakOf(second.capture, "ICMD"));
        QVERIFY(second.currentSaturated);
        QVERIFY(peakOf(second.capture, "ICMD") >= 0.98 * kIlim / 2);
        QVERIFY2(w.panel->warningText().startsWith(QStringLiteral("ICMD reached ILIM in run 2")),
                 qPrintable(w.panel->warningText()));
        // The typed amplitude stays until the user asks for the proposal again.
        QCOMPARE(amplitude->value(), 8 * halved);
        w.panel->useProposedAmplitude();
        QCOMPARE(amplitude->value(), halved);
    }

    // Proposed once, then kept: KV and ILIM changes (and reading the drive's values again) move the "Proposed:"
    // line, not the move, so that every run's overlay is the same J; Propose takes the new value.
    void amplitudeIsProposedOnceAndKeptWhileGainsChange() {
        Window w;
        QVERIFY(w.ready());
        QSpinBox* amplitude = w.amplitudeField();
        QVERIFY(amplitude);
        w.panel->useProposedAmplitude();
        const int taken = amplitude->value();
        QCOMPARE(taken, w.panel->proposedAmplitude());
        const QString move = w.panel->runner<app::TuningRunner>().testMove().description();
        QVERIFY2(move.startsWith(QStringLiteral("J %1 ").arg(taken)), qPrintable(move));

        QSignalSpy confirmed(&w.panel->runner<app::TuningRunner>(), &app::TuningRunner::gainConfirmed);
        w.panel->gainEditor(QStringLiteral("KV"))->setValue(4000); // as the user tunes
        QVERIFY(confirmed.wait(kDriveTimeoutMs));
        w.panel->runner<app::TuningRunner>().setGain(QStringLiteral("ILIM"), kIlim / 2);
        QVERIFY(confirmed.wait(kDriveTimeoutMs));
        QSignalSpy values(&w.panel->runner<app::TuningRunner>(), &app::TuningRunner::driveValuesRead);
        w.panel->runner<app::TuningRunner>().readGains();
        QVERIFY(values.wait(kDriveTimeoutMs));
        const int now = w.panel->proposedAmplitude();
        QVERIFY2(now < taken / 2, qPrintable(QStringLiteral("%1 %2").arg(now).arg(taken))); // KV x2, ILIM / 2
        QVERIFY(w.panel->proposalText().contains(QString::number(now)));
        QCOMPARE(amplitude->value(), taken);
        QCOMPARE(w.panel->runner<app::TuningRunner>().testMove().description(), move);

        w.panel->useProposedAmplitude();
        QCOMPARE(amplitude->value(), now);
        QCOMPARE(w.panel->runner<app::TuningRunner>().testMove().amplitude, now);
    }

    void positionStepMovesByItsAmplitudeAndBack() {
        Window w;
        QVERIFY(w.ready());
        app::TestMove move;
        move.kind = app::TestMove::Kind::PositionStep;
        move.durationMs = 200;
        app::setTestMove(*w.panel, move);
        w.panel->useProposedAmplitude();
        const int counts = w.panel->proposedAmplitude();
        QCOMPARE(w.panel->runner<app::TuningRunner>().testMove().amplitude, counts);
        // At most the velocity step's 136 rad/s (reached in 13 ms at the power-up ACC, 100000 RPM/s) for a quarter
        // of the hold: 136 rad/s x 0.05 s = 6.8 rad = 4430 counts, at that speed.
        QVERIFY2(counts > 3000 && counts < 6000, qPrintable(QString::number(counts)));
        QCOMPARE(w.panel->runner<app::TuningRunner>().testMove().moveVelocity, 1298);

        QVERIFY(w.run());
        const app::TuningRun run = w.panel->runner<app::TuningRunner>().runs().last();
        const scope::CaptureChannel* pcmd = run.capture.find("PCMD");
        const scope::CaptureChannel* pfb = run.capture.find("PFB");
        QVERIFY(pcmd && pfb);
        QCOMPARE(w.panel->view()->plot()->pointCount(1), int(pfb->values.size()));
        const auto [cmdLow, cmdHigh] = std::minmax_element(pcmd->values.begin(), pcmd->values.end());
        QCOMPARE(*cmdHigh - *cmdLow, double(counts)); // MI n, then MI -n
        const double start = pfb->values.front();
        const double reached = *std::max_element(pfb->values.begin(), pfb->values.end()) - start;
        qInfo("MI %d: PFB reached %+.0f counts, ends %+.0f; overshoot %s %%, ICMD peak %.0f", counts, reached,
              pfb->values.back() - start, qPrintable(w.panel->runsTable()->item(0, 2)->text()),
              peakOf(run.capture, "ICMD"));
        QVERIFY2(std::abs(reached - counts) < 0.05 * counts, qPrintable(QString::number(reached)));
        QVERIFY2(std::abs(pfb->values.back() - start) < 0.05 * counts, "PFB is not back where it started");
        QVERIFY(!run.currentSaturated);
        QVERIFY(w.panel->warningText().isEmpty());
        QCOMPARE(w.panel->runsTable()->rowCount(), 1);
        QVERIFY(w.panel->runsTable()->item(0, 3)->text() != QStringLiteral("\u2014")); // a rise time
    }
};

QTEST_MAIN(TuningPresetsTest)
#include "tuning_presets_test.moc"
