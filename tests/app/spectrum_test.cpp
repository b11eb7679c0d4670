// Scope > Spectrum (issue 22) asserting what a user sees. Against the simulated BDS5 with a compliant coupling
// set on the I/O panel's bench: the spectrum of a velocity step marks a peak at the two-mass resonance computed
// here from the closed form, and after LPF=1 with LPFHZ well below it (set in the tuning panel's gain editors)
// the next run's spectrum lies far under the previous run's overlay there. And the view alone: the window
// changes the plotted trace, the readout states the resolution, a weaker second capture reads lower than its
// overlay.
#include "app/families/bds5/bds5_workspace.h"
#include "families/bds5/io_panel.h"
#include "app/scope/scope_controller.h"
#include "app/scope/scope_view.h"
#include "app/scope/spectrum_view.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "app_test_support.h"

#include "drive_core/physics/motor_parameters.h"
#include "scope/capture_csv.h"
#include "scope/math_channel.h"

#include <qcustomplot.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using app::MainWindow;

namespace {
using app_test::driveReady;
using app_test::kDriveTimeoutMs;

constexpr double kPi = std::numbers::pi;

// The plotted trace as (frequency, dB) pairs.
QVector<QPointF> trace(const QCPGraph* graph) {
    QVector<QPointF> points;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        points << QPointF(it->key, it->value);
    return points;
}

double atFrequency(const scope::Spectrum& s, double f) {
    return s.magnitude_db[std::size_t(std::lround(f / s.resolution_hz))];
}

scope::Capture sine(double amplitude, double frequency_hz, const std::string& title) {
    scope::Capture c;
    c.interval_s = 0.001;
    c.title = title;
    c.channels.push_back({"VFB", "VEL", {}});
    for (int i = 0; i < 400; ++i)
        c.channels[0].values.push_back(100 + amplitude * std::sin(2 * kPi * frequency_hz * i * c.interval_s));
    return c;
}

// One tuning run, started as Run Once does; true when it finished.
bool runOnce(app::TuningRunner& runner) {
    QSignalSpy runs(&runner, &app::TuningRunner::runFinished);
    runner.runOnce();
    return runs.wait(2 * kDriveTimeoutMs);
}
} // namespace

class SpectrumTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskSpectrumTest"));
    }

    void resonancePeakOfTheTwoMassBenchDropsUnderTheLowPassFilter() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QVERIFY(QTest::qWaitFor([&] { return driveReady(window); }, kDriveTimeoutMs));

        // The bench: a load as heavy as the rotor on a spring, damped to zeta ~ 0.03 (c = 2 zeta w Jm Jl/(Jm+Jl)).
        // The resonance from the closed form, the rotor's inertia from the reference motor table (the bench's
        // motor at power-up).
        const double jm = drive_core::physics::findReferenceMotor("REF-MEDIUM")->motor.rotorInertia_kgm2;
        const double jl = 1.5e-4, stiffness = 185, damping = 0.007;
        const double resonance_hz = std::sqrt(stiffness * (1 / jm + 1 / jl)) / (2 * kPi); // 250.0 Hz
        app::IoPanel& bench = *window.bds5().ioPanel();
        bench.loadInertiaField()->setValue(jl);
        bench.couplingStiffnessField()->setValue(stiffness);
        bench.couplingDampingField()->setValue(damping);
        QTRY_VERIFY_WITH_TIMEOUT(bench.resonanceText().startsWith(QString::number(resonance_hz, 'f', 1)),
                                 kDriveTimeoutMs);

        app::ScopeController& scope = window.scopeController();
        app::TuningPanel& panel = *scope.tuningPanel();
        app::TuningRunner& runner = panel.runner<app::TuningRunner>();
        // The velocity loop alone at its power-up gains and a true step, as the frequency-response preset wants
        // (see bode_test.cpp).
        runner.setGain(QStringLiteral("PLIM"), 0);
        runner.setGain(QStringLiteral("PL"), 0);
        for (const char* line : {"DIS", "AMAX=1000000", "ACC=1000000", "EN"})
            window.connection().sendCommand(QString::fromLatin1(line));
        QVERIFY(QTest::qWaitFor([&] { return driveReady(window); }, kDriveTimeoutMs));
        app::TestMove move;
        move.kind = app::TestMove::Kind::FrequencyStep;
        move.amplitude = 300;
        move.durationMs = 400;
        app::setTestMove(panel, move);
        QVERIFY(runOnce(runner));

        app::SpectrumView* view = scope.spectrum();
        QVERIFY(view->isVisible());
        QCOMPARE(view->channelBox()->currentText(), QStringLiteral("VFB"));
        QCOMPARE(view->windowBox()->currentText(), QStringLiteral("Hann"));
        // "Peak above: auto" by default: the peak that stands out of its surroundings (scope::findProminentPeak).
        QCOMPARE(view->peakFromBox()->text(), QStringLiteral("auto"));
        QVERIFY2(view->spectrum().ok() && view->peak(), qPrintable(view->readout()));
        const double peak_hz = view->peak()->frequency_hz;
        qInfo("closed-form resonance %.1f Hz; spectrum peak %.1f Hz (%.1f dB); %s", resonance_hz, peak_hz,
              view->peak()->interpolated_db, qPrintable(view->readout()));
        // Within 10 %, not 2 bins (5 Hz): the peak is the closed loop's. The velocity loop reaches the motor
        // through its 1 ms sample and the velocity estimate, well over 90 degrees of lag at 250 Hz; there its
        // push on the motor has a spring-like part that raises the mode (measured: 269 Hz, +8 %) and a part
        // against the damping that makes it ring. Without the coupling there is no peak here at all.
        QVERIFY2(std::abs(peak_hz - resonance_hz) <= 0.1 * resonance_hz,
                 qPrintable(QStringLiteral("peak %1 Hz, resonance %2 Hz").arg(peak_hz).arg(resonance_hz)));
        QVERIFY2(view->readout().contains(QStringLiteral("Peak: %1 Hz").arg(peak_hz, 0, 'f', 1)),
                 qPrintable(view->readout()));
        // A frequency chosen by hand searches above it: the same resonance, said so.
        view->peakFromBox()->setValue(100);
        QVERIFY2(view->peak() && view->peak()->frequency_hz == peak_hz &&
                     view->readout().contains(QStringLiteral("Peak above 100 Hz: %1 Hz").arg(peak_hz, 0, 'f', 1)),
                 qPrintable(view->readout()));
        view->peakFromBox()->setValue(0);
        QVERIFY(!view->overlay());

        // The remedy, as a user sets it in the tuning panel: LPF on, LPFHZ a quarter of the resonance.
        const int lpfHz = int(resonance_hz / 4);
        QSignalSpy confirmed(&runner, &app::TuningRunner::gainConfirmed);
        panel.gainEditor(QStringLiteral("LPFHZ"))->setValue(lpfHz);
        panel.gainSwitch(QStringLiteral("LPF"))->setChecked(true);
        QTRY_COMPARE_WITH_TIMEOUT(confirmed.count(), 2, kDriveTimeoutMs);
        QVERIFY(runOnce(runner));

        QVERIFY2(view->overlay(), "the previous run is not overlaid");
        const double before = atFrequency(*view->overlay(), peak_hz), after = atFrequency(view->spectrum(), peak_hz);
        // Compared where the user saw the peak. Two cascaded one-pole filters at fc pass f at
        // -2 x 10 log10(1 + (f/fc)^2): at 269 Hz with fc = 62 Hz that is -2 x 13.0 = -26 dB on the current
        // command that excites the mode (and on the loop's push that made it ring). The mode's own response
        // changes as the loop lets go of it; 6 dB of the 26 are left for that: at least 20 dB lower.
        constexpr double kDrop_db = 20;
        qInfo("at the peak's %.1f Hz: %.1f dB before, %.1f dB with LPFHZ=%d; %s", peak_hz, before, after, lpfHz,
              qPrintable(view->readout()));
        QVERIFY2(before - after >= kDrop_db, qPrintable(QStringLiteral("%1 -> %2 dB").arg(before).arg(after)));
        QCOMPARE(view->plot()->graphCount(), 2);
        QVERIFY(view->plot()->graph(1)->visible() && view->plot()->graph(1)->dataCount() > 100);
        QVERIFY2(view->readout().contains(QStringLiteral("previous capture's peak %1 Hz").arg(peak_hz, 0, 'f', 1)) &&
                     view->readout().contains(QStringLiteral("dB lower now")),
                 qPrintable(view->readout()));
        window.connection().sendCommand(QStringLiteral("DIS"));
    }

    void windowChoiceChangesThePlotAndTheReadoutStatesTheResolution() {
        app::SpectrumView view;
        view.show();
        QVERIFY(view.readout().startsWith(QStringLiteral("Nothing recorded yet")));
        // 400 samples every 1 ms: bins 2.5 Hz apart; the tone lies between bins, where the windows differ most.
        view.showCapture(sine(50, 101.25, "loud"));
        QVERIFY2(view.readout().contains(QStringLiteral("resolution \u0394f = 2.50 Hz")) &&
                     view.readout().contains(QStringLiteral("0.400 s record of 400 samples every 1 ms")),
                 qPrintable(view.readout()));
        QCOMPARE(view.plot()->xAxis->scaleType(), QCPAxis::stLogarithmic);
        QVERIFY(view.plot()->xAxis->label().contains(QStringLiteral("[Hz]")));
        QCOMPARE(view.plot()->yAxis->label(), QStringLiteral("magnitude [dB re 1 VEL]"));
        const QVector<QPointF> hann = trace(view.plot()->graph(0));
        QCOMPARE(hann.size(), 200); // bins 1 .. N/2
        QVERIFY(std::abs(view.spectrum().peak->frequency_hz - 101.25) < 0.5);

        view.windowBox()->setCurrentText(QStringLiteral("Rectangular"));
        QCOMPARE(view.spectrum().window, scope::SpectrumWindow::Rectangular);
        const QVector<QPointF> rectangular = trace(view.plot()->graph(0));
        QCOMPARE(rectangular.size(), hann.size());
        // Far from the tone the rectangular window's leakage is tens of dB above Hann's.
        QVERIFY2(rectangular[7].y() > hann[7].y() + 20,
                 qPrintable(QStringLiteral("%1 vs %2 dB at 20 Hz").arg(rectangular[7].y()).arg(hann[7].y())));
        QVERIFY(view.readout().contains(QStringLiteral("Rectangular window")));
        view.setLogFrequency(false);
        QCOMPARE(view.plot()->xAxis->scaleType(), QCPAxis::stLinear);

        // A second capture at half the amplitude: the first stays as the overlay, 6 dB above at the peak.
        view.setWindow(scope::SpectrumWindow::Hann);
        view.showCapture(sine(25, 101.25, "quiet"));
        QVERIFY(view.overlay());
        QVERIFY(view.plot()->graph(1)->visible());
        QVERIFY2(view.readout().contains(QStringLiteral("6.0 dB lower now")), qPrintable(view.readout()));
    }

    // A math channel of the Scope is a channel of the spectrum too: 2·VFB reads 6 dB above VFB at its peak, and
    // it leaves the list when the user removes it.
    void mathChannelsAreSpectrumSources() {
        MainWindow window;
        app::ScopeController& scope = window.scopeController();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("tone.csv"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly) &&
                file.write(QByteArray::fromStdString(scope::writeCsv(sine(50, 101.25, "tone")))) > 0);
        file.close();
        QVERIFY(scope.loadCsv(path));
        app::SpectrumView* view = scope.spectrum();
        QCOMPARE(view->channelBox()->currentText(), QStringLiteral("VFB"));
        const double vfb_db = view->peak()->interpolated_db;

        scope::MathChannelSpec doubled;
        doubled.op = scope::MathOp::Scale;
        doubled.a = "VFB";
        doubled.k = 2;
        doubled.name = "2*VFB";
        QVERIFY(scope.view()->addMathChannel(doubled));
        QVERIFY(view->channelBox()->findText(QStringLiteral("2*VFB")) >= 0);
        view->setChannel(QStringLiteral("2*VFB"));
        QVERIFY2(view->spectrum().ok() && view->peak(), qPrintable(view->readout()));
        QVERIFY2(std::abs(view->peak()->interpolated_db - vfb_db - 20 * std::log10(2.0)) < 0.01,
                 qPrintable(view->readout()));

        QVERIFY(scope.view()->removeMathChannel(QStringLiteral("2*VFB")));
        QCOMPARE(view->channelBox()->findText(QStringLiteral("2*VFB")), -1);
        QCOMPARE(view->channelBox()->currentText(), QStringLiteral("VFB"));
    }
};

QTEST_MAIN(SpectrumTest)
#include "spectrum_test.moc"
