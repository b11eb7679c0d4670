// Triggers on Scope > Watch Variables (issue 22) for each drive family, against its simulated drive: a
// position watched at rest, a rising-level trigger set above it with 25 % pre-trigger in Single mode and
// armed; then a move (a BDS5 jog, an SC750 program, a PMC-960 index) carries the position through the level.
// The chart shows the one frame, the trigger sample a quarter of the way in where the value crosses the level,
// at time 0 on the chart, and Single stopped the polls. Waits on the drive's answers only.
#include "family_window.h"
#include "app/main_window.h"
#include "families/pmc960/pmc960_status_dock.h"
#include "families/pmc960/pmc960_workspace.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_workspace.h"
#include "app/scope/scope_controller.h"
#include "app/scope/trigger_bar.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "app/scope/variable_watcher.h"
#include "app/scope/watch_trigger.h"
#include "app/scope/watch_view.h"
#include "app_test_support.h"

#include "editor/program_editor.h"

#include <qcustomplot.h>

#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <cmath>

using app::WatchTrigger;
using app_test::kDriveTimeoutMs;
using drive_core::DriveFamily;

namespace {

constexpr int kFrame = 20; // samples: 5 before the trigger at 25 %

// Watches `name` with a Single rising-level trigger `above` its value at rest, and waits until it is armed
// with its pre-trigger samples taken. Returns the level, NaN if the watch never got that far.
double armAbove(app::WatchView* view, const QString& name, double above) {
    app::TriggerBar* bar = view->triggerBar();
    bar->setMode(scope::TriggerMode::Single);
    bar->setKind(scope::TriggerKind::Level);
    bar->setSlope(scope::TriggerSlope::Rising);
    bar->setPreTrigger(25);
    bar->setFrameSamples(kFrame);
    bar->setLevel(1e9); // nothing reaches it while the value at rest is read
    view->watch({name});
    const app::VariableWatcher& watcher = view->watcher();
    if (!QTest::qWaitFor([&] { return watcher.store().channel(0).samples.size() >= 2; }, kDriveTimeoutMs))
        return std::nan("");
    const double level = watcher.store().channel(0).samples.back().value + above;
    bar->setLevel(level); // re-arms, as on a scope
    const bool armed =
        QTest::qWaitFor([&] { return view->trigger().status() == WatchTrigger::Status::Waiting; }, kDriveTimeoutMs);
    return armed ? level : std::nan("");
}

// The one frame: the trigger sample at 25 % of it, the value crossing the level there, drawn at time 0.
void checkSingleFrame(app::WatchView* view, double level) {
    WatchTrigger& trigger = view->trigger();
    QTRY_VERIFY_WITH_TIMEOUT(trigger.frameCount() == 1, kDriveTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(!view->watcher().isRunning(), kDriveTimeoutMs); // Single stopped the polls
    const scope::TriggerFrame& frame = *trigger.lastFrame();
    QVERIFY(frame.triggered);
    QCOMPARE(frame.time_s.size(), std::size_t(kFrame));
    QCOMPARE(frame.triggerIndex, std::size_t(kFrame / 4));
    const std::vector<double>& v = frame.values[0];
    const std::size_t t = frame.triggerIndex;
    QVERIFY2(v[t - 1] < level && v[t] >= level,
             qPrintable(QStringLiteral("%1 then %2 around the level %3").arg(v[t - 1]).arg(v[t]).arg(level)));
    for (std::size_t i = 0; i + 1 < t; ++i) QVERIFY(v[i] < level); // the pre-trigger part is below it

    // The chart holds exactly the frame, the trigger sample at time 0.
    QCPGraph* graph = view->plot()->graph(0);
    QCOMPARE(graph->dataCount(), kFrame);
    const auto atTrigger = graph->data()->at(int(t));
    QCOMPARE(atTrigger->key, 0.0);
    QCOMPARE(atTrigger->value, v[t]);
    QVERIFY(graph->data()->at(0)->key < 0);
    QCOMPARE(view->plot()->xAxis->label(), QStringLiteral("time from the trigger [s]"));

    QCOMPARE(trigger.status(), WatchTrigger::Status::Stopped);
    QVERIFY2(view->triggerBar()->stateText().startsWith(QStringLiteral("Stopped: Single frame taken")),
             qPrintable(view->triggerBar()->stateText()));
    QVERIFY(view->triggerBar()->armButton()->isEnabled()); // Arm for another
}

} // namespace

class WatchTriggerTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskWatchTriggerTest"));
        QSettings().clear();
    }

    void bds5SingleFrameOfAJogThroughTheLevel() {
        app::MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QVERIFY(QTest::qWaitFor([&] { return app_test::driveReady(window); }, kDriveTimeoutMs));
        window.scopeController().tuningRunner().setGain(QStringLiteral("PLIM"), 0); // PMAX/PMIN off
        window.connection().sendCommand(QStringLiteral("EN"));
        QVERIFY(QTest::qWaitFor([&] { return app_test::driveReady(window); }, kDriveTimeoutMs));

        app::WatchView* view = window.scopeController().watchVariables();
        const double level = armAbove(view, QStringLiteral("PFB"), 200);
        QVERIFY2(!std::isnan(level), qPrintable(view->triggerBar()->stateText()));
        QCOMPARE(view->trigger().status(), WatchTrigger::Status::Waiting);
        QVERIFY2(view->triggerBar()->stateText().startsWith(QStringLiteral("Waiting for PFB")),
                 qPrintable(view->triggerBar()->stateText()));
        window.connection().sendCommand(QStringLiteral("J 100"));
        checkSingleFrame(view, level);
        window.connection().sendCommand(QStringLiteral("J 0"));
    }

    void sc750SingleFrameOfAProgramThroughTheLevel() {
        app::MainWindow window;
        window.show();
        auto& ws = family_window::connectSc750(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kDriveTimeoutMs);
        family_window::newBasProgram(ws, QStringLiteral("ENABLE = 1\nACCEL.RATE = 5000\nRUN.SPEED = 300\nGO.VEL\n"
                                                "Spin:\n  PAUSE.TIME = 0.1\n  PAUSE\nGOTO Spin\n"));
        app::WatchView* view = ws.watchVariables();
        const double level = armAbove(view, QStringLiteral("POSITION"), 50);
        QVERIFY2(!std::isnan(level), qPrintable(view->triggerBar()->stateText()));
        QCOMPARE(view->trigger().status(), WatchTrigger::Status::Waiting);
        ws.debugger().run();
        checkSingleFrame(view, level);
    }

    void pmc960SingleFrameOfAnIndexThroughTheLevel() {
        app::MainWindow window;
        window.show();
        auto& ws = family_window::connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kDriveTimeoutMs);
        app::Pmc960StatusDock* status = ws.statusDock();
        QTRY_VERIFY_WITH_TIMEOUT(status->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM0")),
                                 kDriveTimeoutMs);
        app::WatchView* view = ws.watchVariables();
        const double level = armAbove(view, QStringLiteral("G"), 20000);
        QVERIFY2(!std::isnan(level), qPrintable(view->triggerBar()->stateText()));
        QCOMPARE(view->trigger().status(), WatchTrigger::Status::Waiting);
        status->sendCommand(QStringLiteral("SM2"));
        status->sendCommand(QStringLiteral("I40000+"));
        checkSingleFrame(view, level);
    }
};

QTEST_MAIN(WatchTriggerTest)
#include "watch_trigger_test.moc"
