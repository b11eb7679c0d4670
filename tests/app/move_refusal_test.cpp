// A recording whose test move the drive refused or cut short, against the simulated BDS5 (issue 19): Scope >
// From Drive with the drive disabled (J 1000 -> ERR 50) stops at once and says why instead of reading back
// seconds of zeros and saying "Recorded"; a jog stopped by ERR 23 (the power-up PMAX/PMIN of +-100 counts) is
// not shown; a tuning run the drive refused adds no run, row or overlay; and before a tuning run whose move
// would pass the soft limits the panel asks, turns PLIM off for the test only when told to, and runs nothing
// when cancelled.
#include "app_test_support.h"
#include "families/bds5/drive_connection.h"
#include "app/main_window.h"
#include "app/scope/scope_controller.h"
#include "app/scope/scope_view.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"

#include "scope/scope_plot.h"

#include <QAbstractButton>
#include <QMessageBox>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>

#include <algorithm>

using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;
using app_test::driveReady;

// 250 samples of three variables every 32 ms: the 8 s recording of the report.
serialport::Bds5RecordPlan longJog() {
    serialport::Bds5RecordPlan plan;
    plan.samples = 250;
    plan.intervalMs = 32;
    plan.variables = {QStringLiteral("VCMD"), QStringLiteral("VFB"), QStringLiteral("ICMD")};
    plan.commands = {{0, QStringLiteral("J 1000")}, {4000, QStringLiteral("J 0")}};
    plan.onCancel = QStringLiteral("J 0");
    return plan;
}

serialport::Bds5RecordPlan shortJog() {
    serialport::Bds5RecordPlan plan;
    plan.samples = 160;
    plan.intervalMs = 1;
    plan.variables = {QStringLiteral("VCMD"), QStringLiteral("VFB")};
    plan.commands = {{0, QStringLiteral("J 1000")}, {100, QStringLiteral("J 0")}};
    plan.onCancel = QStringLiteral("J 0");
    return plan;
}

struct Window {
    MainWindow window;
    app::TuningPanel* panel;
    QByteArray sent; // every byte written to the drive
    Window() : panel(window.scopeController().tuningPanel()) {
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QObject::connect(&window.connection(), &app::DriveConnection::rawSent, &window,
                         [this](const QByteArray& bytes) { sent += bytes; });
    }
    // At the prompt with the gains and the drive's values read, as the panel shows them after connecting.
    bool ready() {
        if (!QTest::qWaitFor([this] { return driveReady(window); }, kDriveTimeoutMs)) return false;
        QSignalSpy values(&panel->runner<app::TuningRunner>(), &app::TuningRunner::driveValuesRead);
        panel->runner<app::TuningRunner>().readGains();
        return values.wait(kDriveTimeoutMs);
    }
    // What the drive prints for line (P PLIM), as a user typing it would read it.
    QString ask(const QString& line) {
        serialport::Bds5Session* session = window.connection().session();
        QSignalSpy finished(session, &serialport::Bds5Session::finished);
        const quint64 id = session->send(line, serialport::Bds5Session::Echo::Quiet);
        QString answer;
        const bool answered = QTest::qWaitFor(
            [&] {
                for (const QList<QVariant>& args : finished)
                    if (args.at(0).value<quint64>() == id) {
                        answer = args.at(1).value<serialport::Bds5Response>().lines.join(QLatin1Char(' '));
                        return true;
                    }
                return false;
            },
            kDriveTimeoutMs);
        return answered ? answer.trimmed() : QStringLiteral("(no answer to %1)").arg(line);
    }
    QAbstractButton* button(QMessageBox* box, const QString& text) {
        for (QAbstractButton* b : box->buttons())
            if (b->text().contains(text)) return b;
        return nullptr;
    }
};
} // namespace

class MoveRefusalTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskMoveRefusalTest"));
    }

    // Scope > From Drive, drive disabled: the status bar names the command, the error and the fix; nothing is
    // plotted, and the 8 s recording is never read back (no PLAY goes out).
    void recordStopsWhenTheDriveRefusesTheMove() {
        Window w;
        QVERIFY(QTest::qWaitFor([&w] { return driveReady(w.window); }, kDriveTimeoutMs));
        w.window.connection().sendCommand(QStringLiteral("DIS"));
        app::ScopeController& scope = w.window.scopeController();
        QSignalSpy finished(&scope, &app::ScopeController::recordFinished);
        scope.record(longJog());
        QVERIFY(finished.wait(kDriveTimeoutMs));
        const QString status = w.window.statusBar()->currentMessage();
        QVERIFY2(status.startsWith(QStringLiteral("Record stopped: the drive refused J 1000: ERR 50")) &&
                     status.contains(QStringLiteral("DRIVE INHIBITED")) &&
                     status.contains(QStringLiteral("Enable the drive with EN")),
                 qPrintable(status));
        QVERIFY(!status.contains(QStringLiteral("Recorded")));
        const auto result = finished.first().at(0).value<serialport::Bds5TransferResult>();
        QVERIFY(!result.ok());
        QVERIFY(!scope.lastCapture());
        QCOMPARE(scope.view()->plot()->pointCount(0), 0);
        QVERIFY2(!w.sent.contains("PLAY"), w.sent.constData());
    }

    // A jog that ERR 23 (software overtravel) stopped after a few counts is not a step response.
    void recordCutShortByOvertravelIsNotShown() {
        Window w;
        QVERIFY(QTest::qWaitFor([&w] { return driveReady(w.window); }, kDriveTimeoutMs));
        w.window.connection().sendCommand(QStringLiteral("EN")); // PLIM on, PMAX/PMIN +-100: as at power-up
        app::ScopeController& scope = w.window.scopeController();
        QSignalSpy finished(&scope, &app::ScopeController::recordFinished);
        scope.record(shortJog());
        QVERIFY(finished.wait(kDriveTimeoutMs));
        const QString status = w.window.statusBar()->currentMessage();
        QVERIFY2(status.startsWith(QStringLiteral("Record stopped: the drive reported ERR 23 SOFTWARE OVERTRAVEL")) &&
                     status.contains(QStringLiteral("PLIM OFF")),
                 qPrintable(status));
        QVERIFY(!scope.lastCapture());
        QCOMPARE(scope.view()->plot()->pointCount(1), 0);
    }

    // The tuning panel: the refused run says so and leaves no row, overlay or run number behind; the next
    // run, with the drive enabled, is run 1.
    void refusedTuningRunAddsNoRowOrOverlay() {
        Window w;
        QVERIFY(w.ready());
        app::TuningRunner& runner = w.panel->runner<app::TuningRunner>();
        runner.setGain(QStringLiteral("PLIM"), 0); // the soft limits are not what this test is about
        w.window.connection().sendCommand(QStringLiteral("DIS"));
        QSignalSpy failed(&runner, &app::TuningRunner::runFailed);
        QSignalSpy runs(&runner, &app::TuningRunner::runFinished);
        runner.runOnce();
        QVERIFY(failed.wait(kDriveTimeoutMs));
        const QString status = w.panel->statusText();
        QVERIFY2(status.startsWith(QStringLiteral("Run 1 stopped: the drive refused J ")) &&
                     status.contains(QStringLiteral("ERR 50")) &&
                     status.contains(QStringLiteral("No row or overlay was added")),
                 qPrintable(status));
        QVERIFY(!status.contains(QStringLiteral("overshoot")));
        QCOMPARE(runs.count(), 0);
        QVERIFY(runner.runs().isEmpty());
        QCOMPARE(w.panel->runsTable()->rowCount(), 0);
        QCOMPARE(w.panel->view()->plot()->overlayCount(), 0);
        QCOMPARE(w.panel->view()->plot()->pointCount(0), 0);
        QVERIFY(!runner.isRunning());

        w.window.connection().sendCommand(QStringLiteral("EN"));
        runner.runOnce();
        QVERIFY(runs.wait(kDriveTimeoutMs));
        QCOMPARE(w.panel->runsTable()->rowCount(), 1);
        QCOMPARE(w.panel->runsTable()->item(0, 0)->text(), QStringLiteral("1"));
        QCOMPARE(w.panel->view()->plot()->overlayCount(), 0);
    }

    // A newcomer's first run with the power-up limits: asked before anything moves; "turn off" runs the test
    // with PLIM=0 and puts PLIM back on after it.
    void softLimitsAreAskedAboutAndTurnedOffForTheTestOnly() {
        Window w;
        QVERIFY(w.ready());
        w.window.connection().sendCommand(QStringLiteral("EN"));
        app::TuningRunner& runner = w.panel->runner<app::TuningRunner>();
        QSignalSpy runs(&runner, &app::TuningRunner::runFinished);
        QSignalSpy failed(&runner, &app::TuningRunner::runFailed);
        runner.runOnce();
        QVERIFY(QTest::qWaitFor(
            [&w] { return app::softLimitsQuestion(*w.panel) && app::softLimitsQuestion(*w.panel)->isVisible(); },
            kDriveTimeoutMs));
        QMessageBox* question = app::softLimitsQuestion(*w.panel);
        QVERIFY2(question->text().contains(QStringLiteral("PMAX 100")) &&
                     question->text().contains(QStringLiteral("ERR 23")),
                 qPrintable(question->text()));
        QVERIFY(w.panel->statusText().startsWith(QStringLiteral("Waiting")));
        QVERIFY(runner.isWaitingForAnswer());
        QVERIFY(!w.sent.contains("RECORD")); // nothing moved while the question is open
        QAbstractButton* off = w.button(question, QStringLiteral("PLIM=0"));
        QVERIFY(off);
        off->click();
        QVERIFY(runs.wait(kDriveTimeoutMs));
        QCOMPARE(failed.count(), 0);
        const app::TuningRun run = runner.runs().last();
        QVERIFY(run.softLimitsOff);
        const scope::CaptureChannel* vcmd = run.capture.find("VCMD");
        QVERIFY(vcmd);
        // The whole step was run: the command reached the amplitude and held it (no ERR 23 stop).
        QCOMPARE(*std::max_element(vcmd->values.begin(), vcmd->values.end()), double(runner.testMove().amplitude));
        QVERIFY2(w.panel->statusText().contains(QStringLiteral("PLIM=0")), qPrintable(w.panel->statusText()));
        // The run's gains are the user's: undo to this run never turns the limits off.
        QCOMPARE(run.gains.value(QStringLiteral("PLIM")), 1);
        QTRY_VERIFY_WITH_TIMEOUT(!runner.isRunning(), kDriveTimeoutMs);
        QCOMPARE(w.ask(QStringLiteral("P PLIM")), QStringLiteral("1")); // the limits are back
    }

    // Cancel: no run, and the status says why; with limits set wide enough for the move, no question at all.
    void cancelledSoftLimitsQuestionRunsNothing() {
        Window w;
        QVERIFY(w.ready());
        w.window.connection().sendCommand(QStringLiteral("EN"));
        app::TuningRunner& runner = w.panel->runner<app::TuningRunner>();
        QSignalSpy asked(&runner, &app::TuningRunner::softLimitsInTheWay);
        QSignalSpy runs(&runner, &app::TuningRunner::runFinished);
        runner.runOnce();
        QVERIFY(QTest::qWaitFor(
            [&w] { return app::softLimitsQuestion(*w.panel) && app::softLimitsQuestion(*w.panel)->isVisible(); },
            kDriveTimeoutMs));
        app::softLimitsQuestion(*w.panel)->button(QMessageBox::Cancel)->click();
        QVERIFY(!runner.isRunning());
        QVERIFY2(w.panel->statusText().startsWith(QStringLiteral("Not run: the test move would pass the software")),
                 qPrintable(w.panel->statusText()));
        QCOMPARE(w.panel->runsTable()->rowCount(), 0);
        QVERIFY(!w.sent.contains("RECORD"));
        QCOMPARE(w.ask(QStringLiteral("P PLIM")), QStringLiteral("1"));

        w.window.connection().sendCommand(QStringLiteral("PMAX=100000000"));
        w.window.connection().sendCommand(QStringLiteral("PMIN=-100000000"));
        runner.runOnce();
        QVERIFY(runs.wait(kDriveTimeoutMs));
        QCOMPARE(asked.count(), 1); // only the first time
        QVERIFY(!runner.runs().last().softLimitsOff);
        QCOMPARE(w.panel->runsTable()->rowCount(), 1);
    }
};

QTEST_MAIN(MoveRefusalTest)
#include "move_refusal_test.moc"
