// Tuning the SC750 and the PMC-960 in the IDE (issue 18): the Tuning Panel of each family reads the gains from
// the simulated drive, runs its manual's test move, and shows the response the bench's oscilloscope saw on the
// analog monitor output (SC750 DACMON at DACMAP 1, the PMC-960's tach) with its measurements; a gain raised
// makes the next run faster, and undo puts the earlier run's gains back on the drive. The Frequency Response
// of a run (the bench's command probe against its output) widens with the velocity gain. On a serial port the
// runner polls the speed instead.
#include "app/main_window.h"
#include "families/pmc960/pmc960_workspace.h"
#include "families/sc750/sc750_workspace.h"
#include "app/scope/bode_view.h"
#include "app/scope/scope_view.h"
#include "app/tuning/family_tuning_runner.h"
#include "app/tuning/tuning_panel.h"

#include "scope/scope_plot.h"

#include <qcustomplot.h>

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QProcess>
#include <QPushButton>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include "serialport/drive_session.h"
#include "serialport/pmc960_parameter_file.h"
#include "serialport/sc750_parameter_file.h"

#include <QFile>
#include <QFileDialog>

#include <algorithm>

using app::TuningPanel;
using app::MainWindow;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 60000; // a loaded machine stalls; the runs themselves are under a second of drive time

QDockWidget* tuningDock(app::FamilyWorkspace& ws) {
    for (QDockWidget* dock : ws.docks())
        if (dock->objectName().endsWith(QLatin1String("TuningDock"))) return dock;
    return nullptr;
}

QPushButton* button(QWidget* panel, const QString& text) {
    for (QPushButton* b : panel->findChildren<QPushButton*>())
        if (b->text() == text) return b;
    return nullptr;
}

// Shows a window connected to the family's simulated drive; its workspace, or nullptr when it did not connect.
app::FamilyWorkspace* connectSimulated(MainWindow& window, DriveFamily family) {
    window.resize(1280, 800);
    window.show();
    window.connectDrive(app::ConnectionChoice::simulator(family));
    app::FamilyWorkspace* ws = window.workspace(family);
    return ws && QTest::qWaitFor([ws] { return ws->isConnected(); }, kTimeoutMs) ? ws : nullptr;
}

// Opens the family's Tuning Panel from its menu and waits until the gains are read.
TuningPanel* openPanel(MainWindow& window, app::FamilyWorkspace& ws, const QString& gain) {
    QDockWidget* dock = tuningDock(ws);
    if (!dock) return nullptr;
    QAction* action = nullptr;
    for (QMenu* menu : ws.menus())
        for (QAction* a : menu->actions())
            if (a->text() == QStringLiteral("Tuning &Panel")) action = a;
    if (!action) return nullptr;
    action->trigger();
    if (!dock->isVisible()) return nullptr;
    auto* panel = qobject_cast<TuningPanel*>(dock->widget());
    if (!panel) return nullptr;
    if (!QTest::qWaitFor([&] { return panel->gainMark(gain) == QStringLiteral("\u2713"); }, kTimeoutMs)) return nullptr;
    Q_UNUSED(window);
    return panel;
}

// Runs once and waits for the run's row; returns that run.
const app::FamilyTuningRun* runOnce(TuningPanel& panel) {
    const int rows = panel.runsTable()->rowCount();
    button(&panel, QStringLiteral("Run Once"))->click();
    if (!QTest::qWaitFor([&] { return panel.runsTable()->rowCount() == rows + 1; }, kTimeoutMs)) return nullptr;
    return &panel.runner<app::FamilyTuningRunner>().runs().back();
}

// The plot as drawn now.
QImage plotImage(app::ScopeView* view) {
    scope::ScopePlot* plot = view->plot();
    if (!QTest::qWaitForWindowExposed(plot)) return {};
    plot->customPlot()->replot(QCustomPlot::rpImmediateRefresh);
    return plot->grab().toImage();
}

// The plot draws the run: its points, and many pixels changed from the empty plot `before`.
bool plotted(app::ScopeView* view, const QImage& before) {
    if (view->plot()->pointCount(0) < 100) return false;
    const QImage after = plotImage(view);
    if (qEnvironmentVariableIsSet("FAMILY_TUNING_SHOT")) after.save(qEnvironmentVariable("FAMILY_TUNING_SHOT"));
    if (after.size() != before.size()) return false;
    int changed = 0;
    for (int y = 0; y < after.height(); ++y)
        for (int x = 0; x < after.width(); ++x) changed += after.pixel(x, y) != before.pixel(x, y);
    return changed > 300;
}

// The -3 dB bandwidth of the velocity loop in run `row` of the table, from the panel's Frequency Response
// (the bench's command probe against its monitor output); 0 when there is none.
double bandwidthOfRow(TuningPanel& panel, int row, QString* summary = nullptr) {
    panel.runsTable()->selectRow(row);
    app::BodeView* bode = panel.frequencyResponse();
    if (!bode || !bode->isVisible()) return 0;
    if (summary) *summary = bode->summary();
    return bode->response().bandwidth_hz.value_or(0);
}

// The mean of the capture's samples from `from` to `to` seconds after its start.
double meanBetween(const scope::Capture& c, double from, double to) {
    const auto& v = c.channels.front().values;
    double sum = 0;
    int n = 0;
    for (std::size_t i = std::size_t(from / c.interval_s); i < v.size() && double(i) * c.interval_s < to; ++i, ++n)
        sum += v[i];
    return n ? sum / n : 0;
}
} // namespace

class FamilyTuningTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskFamilyTuningTest"));
        QSettings().clear();
    }

    // SC750: a velocity step of 200 RPM shows on DACMON at the manual's 1 V/kRPM (L2147-L2161); KVP doubled
    // halves the rise; undo to run 1 puts KVP back on the drive, as Read from Drive then shows.
    void sc750VelocityStepOnDacmonAndKvp() {
        MainWindow window;
        app::FamilyWorkspace* connected = connectSimulated(window, DriveFamily::Sc750);
        QVERIFY(connected);
        auto& ws = *connected;
        TuningPanel* panel = openPanel(window, ws, QStringLiteral("KVP"));
        QVERIFY(panel);
        const QImage empty = plotImage(panel->view());
        // The sliders line up: every value is as wide as KVP's "0.174000 A/(rad/s)".
        QSet<int> sliderEnds;
        for (const QString name : {"KVP", "KVI", "KPP", "KVFF", "ARF0"})
            sliderEnds << panel->gainEditor(name)->mapTo(panel, QPoint()).x();
        QCOMPARE(sliderEnds.size(), 1);
        const double kvp = panel->gainEditor(QStringLiteral("KVP"))->value();
        QVERIFY(kvp > 0);
        panel->gainEditor(QStringLiteral("KVFF"))->setValue(100); // the velocity loop sees the step itself
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("KVFF")), QStringLiteral("\u2713"), kTimeoutMs);
        panel->movePreset()->setCurrentIndex(0); // velocity step
        panel->amplitude()->setValue(200);
        QVERIFY2(panel->amplitude()->toolTip().startsWith(QStringLiteral("Amplitude in RPM. GO.VEL at RUN.SPEED")),
                 qPrintable(panel->amplitude()->toolTip()));
        panel->hold()->setValue(150);

        const app::FamilyTuningRun* first = runOnce(*panel);
        QVERIFY2(first, qPrintable(panel->statusText()));
        QVERIFY(first->metrics.hasStep);
        QVERIFY(first->metrics.rise_s.has_value());
        QVERIFY(first->source.contains(QStringLiteral("DACMON: VELOCITY, 1 V/kRPM")));
        // 200 RPM at 1 V per kRPM, late in the hold.
        const double plateau = meanBetween(first->capture, 0.1, 0.16);
        QVERIFY2(std::abs(plateau - 0.2) < 0.01, qPrintable(QString::number(plateau)));
        QVERIFY(plotted(panel->view(), empty));
        const double rise1 = *first->metrics.rise_s;

        QSignalSpy confirmed(&panel->runner<app::FamilyTuningRunner>(), &app::FamilyTuningRunner::gainConfirmed);
        panel->gainEditor(QStringLiteral("KVP"))->setValue(2 * kvp);
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("KVP")), QStringLiteral("\u2713"), kTimeoutMs);
        QCOMPARE(confirmed.count(), 1);
        confirmed.clear();
        const app::FamilyTuningRun* second = runOnce(*panel);
        QVERIFY2(second, qPrintable(panel->statusText()));
        QVERIFY(second->metrics.rise_s.has_value());
        QVERIFY2(*second->metrics.rise_s < 0.8 * rise1,
                 qPrintable(QStringLiteral("%1 vs %2").arg(*second->metrics.rise_s).arg(rise1)));
        QVERIFY(panel->runsTable()->item(1, 1)->text().startsWith(QStringLiteral("KVP=")));

        // The velocity loop's frequency response from the bench's second probe (VEL.CMD -> DACMON): near the
        // crossover the default KVP was designed for (KVP Kt / J = 327 rad/s, 52 Hz: DECISIONS 49), and wider
        // with KVP doubled.
        QString summary;
        const double bandwidth1 = bandwidthOfRow(*panel, 0, &summary);
        QVERIFY2(summary.contains(QStringLiteral("VEL.CMD \u2192 DACMON")), qPrintable(summary));
        QVERIFY2(bandwidth1 > 0.6 * 52 && bandwidth1 < 2.5 * 52, qPrintable(summary));
        const double bandwidth2 = bandwidthOfRow(*panel, 1, &summary);
        QVERIFY2(bandwidth2 > 1.3 * bandwidth1, qPrintable(QStringLiteral("%1 vs %2: %3").arg(bandwidth2).arg(bandwidth1).arg(summary)));
        QVERIFY(panel->frequencyResponse()->plot()->graphCount() == 2);
        panel->frequencyResponse()->close();

        panel->runsTable()->selectRow(0);
        button(panel, QStringLiteral("Undo to Selected Run's Gains"))->click();
        QTRY_COMPARE_WITH_TIMEOUT(confirmed.count(), 1, kTimeoutMs); // KVP back
        panel->gainEditor(QStringLiteral("KVP"))->blockSignals(true);
        panel->gainEditor(QStringLiteral("KVP"))->setValue(0); // only the drive's answer can bring it back
        panel->gainEditor(QStringLiteral("KVP"))->blockSignals(false);
        button(panel, QStringLiteral("Read from Drive"))->click();
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainEditor(QStringLiteral("KVP"))->value(), kvp, kTimeoutMs);
    }

    // Save Gains writes the gains the drive holds in the family's own file, as Variables > Send to Drive takes it
    // back: the SC750's PARAMS block (.PRM, L943-L975) and the PMC-960's T-table lines between SW1 and SW0.
    void saveGainsWritesTheFamilysFile_data() {
        QTest::addColumn<DriveFamily>("family");
        QTest::addColumn<QString>("gain");
        QTest::addColumn<QString>("line"); // what the file says for it, %1 the value
        QTest::newRow("sc750") << DriveFamily::Sc750 << QStringLiteral("KVI") << QStringLiteral("KVI = %1");
        QTest::newRow("pmc960") << DriveFamily::Pmc960 << QStringLiteral("VLGAIN") << QStringLiteral("TGV%1");
    }
    void saveGainsWritesTheFamilysFile() {
        QFETCH(DriveFamily, family);
        QFETCH(QString, gain);
        QFETCH(QString, line);
        MainWindow window;
        app::FamilyWorkspace* ws = connectSimulated(window, family);
        QVERIFY(ws);
        TuningPanel* panel = openPanel(window, *ws, gain);
        QVERIFY(panel);
        const double value = panel->gainEditor(gain)->value();
        QTemporaryDir dir;
        const QString path = dir.filePath(panel->tuner().gainsFile()->defaultName);
        QPushButton* save = button(panel, QStringLiteral("Save Gains..."));
        QVERIFY(save);
        save->click();
        auto* dialog = panel->findChild<QFileDialog*>();
        QVERIFY(dialog);
        dialog->selectFile(path);
        QMetaObject::invokeMethod(dialog, "accept", Qt::DirectConnection); // as the Save button does
        QCOMPARE(panel->statusText(), QStringLiteral("Saved the gains to %1.").arg(path));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromLatin1(file.readAll());
        QVERIFY2(text.contains(line.arg(value)), qPrintable(text));
        if (family == DriveFamily::Sc750) {
            const auto parsed = serialport::Sc750ParameterFile::parse(text);
            QVERIFY(parsed.problems().isEmpty());
            QCOMPARE(parsed.assignments().size(), panel->tuner().tunerGains().size());
        } else {
            const auto parsed = serialport::Pmc960ParameterFile::parse(text);
            QVERIFY(parsed.problems().isEmpty());
            QCOMPARE(parsed.lines().size(), panel->tuner().tunerGains().size() + 2); // SW1 ... SW0
        }
    }

    // PMC-960 (4.8.1): the velocity-loop jog in SM1 shows on the tach; VLGAIN (TGV) doubled makes the rise
    // shorter, and TG? reads the new value back.
    void pmc960TachRiseFollowsVlgain() {
        MainWindow window;
        app::FamilyWorkspace* connected = connectSimulated(window, DriveFamily::Pmc960);
        QVERIFY(connected);
        auto& ws = *connected;
        TuningPanel* panel = openPanel(window, ws, QStringLiteral("VLGAIN"));
        QVERIFY(panel);
        tuningDock(ws)->setFloating(true); // at the tour's size: a plot the user reads, beside the gains
        tuningDock(ws)->resize(1240, 600);
        const QImage empty = plotImage(panel->view());
        panel->gainEditor(QStringLiteral("FFGAIN"))->setValue(100); // 4.8.1: TGF100 for the velocity test
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("FFGAIN")), QStringLiteral("\u2713"), kTimeoutMs);
        panel->gainEditor(QStringLiteral("VLGAIN"))->setValue(4);
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("VLGAIN")), QStringLiteral("\u2713"), kTimeoutMs);
        panel->movePreset()->setCurrentIndex(0); // velocity loop, SM1
        panel->hold()->setValue(200);
        const app::FamilyTuningRun* slow = runOnce(*panel);
        QVERIFY2(slow && slow->metrics.rise_s, qPrintable(panel->statusText()));
        QVERIFY(slow->source.contains(QStringLiteral("tach")));
        QVERIFY(plotted(panel->view(), empty));
        const double rise1 = *slow->metrics.rise_s;

        // Run Once right after the change, as a user clicks: the run goes out after the gain's SW1 TGV16 SW0.
        // A busy GUI thread reads each answer 150 ms after the drive gave it (the stall is the condition under
        // test, not a wait): the run must still capture its step, which happens when the jog line is sent.
        QVERIFY(ws.driveSession());
        const QMetaObject::Connection stall = connect(ws.driveSession(), &serialport::DriveSession::answered, this,
                                                      [] { QThread::msleep(150); });
        panel->gainEditor(QStringLiteral("VLGAIN"))->setValue(16);
        const app::FamilyTuningRun* fast = runOnce(*panel);
        disconnect(stall);
        QCOMPARE(panel->runsTable()->item(1, 1)->text(), QStringLiteral("VLGAIN=16"));
        QVERIFY2(fast && fast->metrics.rise_s, qPrintable(panel->statusText()));
        QVERIFY2(*fast->metrics.rise_s < 0.7 * rise1, qPrintable(QStringLiteral("%1 vs %2").arg(*fast->metrics.rise_s).arg(rise1)));
        // The jog starts 20 ms in and rises to the top: the legend is not left over the rise the user tunes.
        QVERIFY(!plotImage(panel->view()).isNull());
        QCOMPARE(panel->view()->plot()->tracesUnderLegend(), 0);

        // The velocity loop's frequency response (the summing junction's command -> the tach): four times
        // VLGAIN, a wider loop.
        QString summary;
        const double bandwidth4 = bandwidthOfRow(*panel, 0, &summary);
        QVERIFY2(bandwidth4 > 0, qPrintable(summary));
        const double bandwidth16 = bandwidthOfRow(*panel, 1, &summary);
        QVERIFY2(summary.contains(QStringLiteral("velocity command \u2192 tach")), qPrintable(summary));
        QVERIFY2(bandwidth16 > 2 * bandwidth4, qPrintable(QStringLiteral("%1 vs %2: %3").arg(bandwidth16).arg(bandwidth4).arg(summary)));
        panel->frequencyResponse()->close();

        panel->gainEditor(QStringLiteral("VLGAIN"))->blockSignals(true);
        panel->gainEditor(QStringLiteral("VLGAIN"))->setValue(1);
        panel->gainEditor(QStringLiteral("VLGAIN"))->blockSignals(false);
        button(panel, QStringLiteral("Read from Drive"))->click();
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainEditor(QStringLiteral("VLGAIN"))->value(), 16.0, kTimeoutMs);
    }

    // A gain that makes the drive fault is seen, not measured as if nothing happened: with the position loop off
    // (KPP 0, KVFF 0) the motor does not follow a 3,000 RPM step and the following error passes 32,767 counts
    // (F 1, DECISIONS 56; L1522-L1588). The run is marked with the fault, Run Continuously stops at it, and the
    // next run clears it (ENABLE=0, then the runs' ENABLE=1) and measures again.
    void sc750FaultDuringARunIsShownAndCleared() {
        MainWindow window;
        app::FamilyWorkspace* connected = connectSimulated(window, DriveFamily::Sc750);
        QVERIFY(connected);
        auto& ws = *connected;
        TuningPanel* panel = openPanel(window, ws, QStringLiteral("KPP"));
        QVERIFY(panel);
        const double kpp = panel->gainEditor(QStringLiteral("KPP"))->value();
        QVERIFY(kpp > 0);
        for (const char* gain : {"KVFF", "KPP"}) {
            panel->gainEditor(QString::fromLatin1(gain))->setValue(0);
            QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QString::fromLatin1(gain)), QStringLiteral("\u2713"), kTimeoutMs);
        }
        panel->movePreset()->setCurrentIndex(0);
        panel->amplitude()->setValue(3000);
        panel->hold()->setValue(300);
        button(panel, QStringLiteral("Run Continuously"))->click();
        QTRY_VERIFY_WITH_TIMEOUT(panel->runsTable()->rowCount() == 1, kTimeoutMs);
        const app::FamilyTuningRun& faulted = panel->runner<app::FamilyTuningRunner>().runs().back();
        QVERIFY2(faulted.fault.startsWith(QStringLiteral("F 1")), qPrintable(faulted.fault + " / " + panel->statusText()));
        QVERIFY(!panel->runner<app::FamilyTuningRunner>().isRunning()); // a continuous series starts its next run as the last one ends
        QVERIFY(!panel->runner<app::FamilyTuningRunner>().isContinuous());
        QVERIFY(panel->runsTable()->item(0, 5)->text().startsWith(QStringLiteral("FAULT F 1")));
        QVERIFY2(panel->statusText().contains(QStringLiteral("faulted")) &&
                     panel->statusText().contains(QStringLiteral("ENABLE=0")),
                 qPrintable(panel->statusText()));

        panel->gainEditor(QStringLiteral("KPP"))->setValue(kpp);
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("KPP")), QStringLiteral("\u2713"), kTimeoutMs);
        panel->gainEditor(QStringLiteral("KVFF"))->setValue(100);
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("KVFF")), QStringLiteral("\u2713"), kTimeoutMs);
        panel->amplitude()->setValue(200);
        const app::FamilyTuningRun* cleared = runOnce(*panel);
        QVERIFY2(cleared, qPrintable(panel->statusText()));
        QVERIFY2(cleared->fault.isEmpty(), qPrintable(cleared->fault));
        QVERIFY2(cleared->metrics.hasStep, qPrintable(panel->statusText()));
        const double plateau = meanBetween(cleared->capture, 0.1 + 0.02, 0.3); // 200 RPM at 1 V/kRPM
        QVERIFY2(std::abs(plateau - 0.2) < 0.01, qPrintable(QString::number(plateau)));
    }

    // PMC-960: the following-error trip (SF, L1505-L1517) in the position loop returns the drive to IDLE with
    // #E1 (L223, L2382). With SF 8 and FFGAIN off, the SM2 jog's following error passes the trip point: the
    // run shows E1, and the next run (after SF back at its power-up 2048) clears it with SM0 and measures.
    void pmc960FollowingErrorTripIsShownAndCleared() {
        MainWindow window;
        app::FamilyWorkspace* connected = connectSimulated(window, DriveFamily::Pmc960);
        QVERIFY(connected);
        auto& ws = *connected;
        TuningPanel* panel = openPanel(window, ws, QStringLiteral("FFGAIN"));
        QVERIFY(panel);
        panel->gainEditor(QStringLiteral("FFGAIN"))->setValue(0);
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("FFGAIN")), QStringLiteral("\u2713"), kTimeoutMs);
        QVERIFY(ws.driveSession());
        QSignalSpy answered(ws.driveSession(), &serialport::DriveSession::answered);
        const quint64 sf = ws.driveSession()->sendLine(QStringLiteral("SF8")); // as typed in the terminal
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(answered.begin(), answered.end(),
                                             [sf](const QList<QVariant>& a) { return a.at(0).toULongLong() == sf; }),
                                 kTimeoutMs);
        panel->movePreset()->setCurrentIndex(1); // position loop, SM2
        panel->hold()->setValue(200);
        const app::FamilyTuningRun* tripped = runOnce(*panel);
        QVERIFY2(tripped, qPrintable(panel->statusText()));
        QVERIFY2(tripped->fault.startsWith(QStringLiteral("#E1")), qPrintable(tripped->fault + " / " + panel->statusText()));
        QVERIFY(panel->runsTable()->item(0, 5)->text().startsWith(QStringLiteral("FAULT #E1")));
        QVERIFY2(panel->statusText().contains(QStringLiteral("SM0")), qPrintable(panel->statusText()));

        answered.clear();
        const quint64 back = ws.driveSession()->sendLine(QStringLiteral("SF2048"));
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(answered.begin(), answered.end(),
                                             [back](const QList<QVariant>& a) { return a.at(0).toULongLong() == back; }),
                                 kTimeoutMs);
        const app::FamilyTuningRun* cleared = runOnce(*panel);
        QVERIFY2(cleared, qPrintable(panel->statusText()));
        QVERIFY2(cleared->fault.isEmpty(), qPrintable(cleared->fault));
        QVERIFY2(cleared->metrics.hasStep, qPrintable(panel->statusText()));
    }

    // A drive on a serial port (servodesk-sim behind a pty: the bytes a real PMC-960 would get) has no bench
    // oscilloscope: the runner polls V! while the jog runs and measures that, saying so and at what rate.
    // This test needs real time (a real process and port); each wait ends at its event, and ctest stretches the
    // port's time-outs for a loaded machine (SERVODESK_TIMEOUT_SCALE in tests/app/CMakeLists.txt).
    void pmc960OnAPortPollsTheSpeed() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString link = dir.filePath(QStringLiteral("drive"));
        QProcess sim;
        sim.setProgram(QStringLiteral(SERVODESK_SIM));
        sim.setArguments({QStringLiteral("--drive"), QStringLiteral("pmc960"), QStringLiteral("--pty"),
                          QStringLiteral("--link"), link});
        sim.start();
        QVERIFY(sim.waitForStarted(kTimeoutMs));
        QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), kTimeoutMs);
        MainWindow window;
        window.resize(1280, 800);
        window.show();
        app::ConnectionChoice choice = app::ConnectionChoice::serialPort(link, 9600);
        choice.family = DriveFamily::Pmc960;
        window.connectDrive(choice);
        auto& ws = *window.workspace(DriveFamily::Pmc960);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        TuningPanel* panel = openPanel(window, ws, QStringLiteral("VLGAIN"));
        QVERIFY(panel);
        panel->gainEditor(QStringLiteral("FFGAIN"))->setValue(100);
        QTRY_COMPARE_WITH_TIMEOUT(panel->gainMark(QStringLiteral("FFGAIN")), QStringLiteral("\u2713"), kTimeoutMs);
        panel->movePreset()->setCurrentIndex(0);
        panel->hold()->setValue(600);
        // The plateau V! showed during a jog of `amplitude`: the value most samples had away from rest.
        const auto plateau = [&](int amplitude, QString* why) {
            panel->amplitude()->setValue(amplitude);
            const app::FamilyTuningRun* run = runOnce(*panel);
            if (!run) return 0.0;
            *why = run->source;
            if (!run->source.startsWith(QStringLiteral("V polled")) || run->capture.channels.size() != 1) return 0.0;
            QMap<double, int> counts;
            for (double v : run->capture.channels.front().values) counts[v] += v != 0;
            return std::max_element(counts.begin(), counts.end()).key();
        };
        QString why;
        const double slow = plateau(41, &why);
        QVERIFY2(slow > 0, qPrintable(why + QLatin1Char(' ') + panel->statusText()));
        // Twice the jog, twice the speed V! reports (a relation: V!'s units are the drive's own, L833).
        const double fast = plateau(82, &why);
        QVERIFY2(std::abs(fast / slow - 2) < 0.1, qPrintable(QStringLiteral("%1 then %2: %3").arg(slow).arg(fast).arg(why)));
        sim.kill();
        sim.waitForFinished(kTimeoutMs);
    }
};

QTEST_MAIN(FamilyTuningTest)
#include "family_tuning_test.moc"
