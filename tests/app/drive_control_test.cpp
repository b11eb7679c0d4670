// Terminal and drive control against the simulated BDS5: command history (F3, Up/Down, kept across
// restarts, capped), ^X overtaking a long queue of commands and stopping motion in time, the Drive
// actions following the drive's mode, and Run Label offering the labels of the program in the editor.
#include "app_test_support.h"
#include "families/bds5/drive_actions.h"
#include "families/bds5/drive_connection.h"
#include "families/bds5/run_label_dialog.h"
#include "app/main_window.h"
#include "app/drive/terminal_widget.h"

#include "editor/program_editor.h"
#include "serialport/bds5_session.h"
#include "serialport/simulator_link.h"

#include <QAction>
#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

#include <algorithm>

using app::MainWindow;
using serialport::Bds5Session;

namespace {
using app_test::kDriveTimeoutMs;

QStringList terminalLines(const MainWindow& window) {
    return window.terminal()->text().split(QLatin1Char('\n'));
}

bool endsWithLines(const MainWindow& window, const QStringList& tail) {
    const QStringList lines = terminalLines(window);
    return lines.size() >= tail.size() && lines.mid(lines.size() - tail.size()) == tail;
}

bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == Bds5Session::State::Ready;
}

void typeLine(MainWindow& window, const QString& line) {
    QTest::keyClicks(window.terminal(), line);
    QTest::keyClick(window.terminal(), Qt::Key_Return);
}
} // namespace

class DriveControlTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskDriveControlTest"));
    }
    void init() { QSettings().clear(); }

    void f3RecallsTheLastCommandAndUpDownBrowse() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && terminalLines(window).last() == QStringLiteral("-->"),
                                 kDriveTimeoutMs);
        typeLine(window, QStringLiteral("P 12"));
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && terminalLines(window).last() == QStringLiteral("-->"),
                                 kDriveTimeoutMs);
        typeLine(window, QStringLiteral("P 345"));
        QTRY_VERIFY_WITH_TIMEOUT(endsWithLines(window, {QStringLiteral("         345"),
                                                                 QStringLiteral("-->")}),
                                 kDriveTimeoutMs);

        // F3: Motion Link's LAST COMMAND. The drive echoes the recalled line; nothing is echoed locally.
        QTest::keyClick(window.terminal(), Qt::Key_F3);
        QTRY_COMPARE_WITH_TIMEOUT(terminalLines(window).last(), QStringLiteral("-->P 345"), kDriveTimeoutMs);
        QTest::keyClick(window.terminal(), Qt::Key_Up);
        QTRY_COMPARE_WITH_TIMEOUT(terminalLines(window).last(), QStringLiteral("-->P 12"), kDriveTimeoutMs);
        QTest::keyClick(window.terminal(), Qt::Key_Down);
        QTRY_COMPARE_WITH_TIMEOUT(terminalLines(window).last(), QStringLiteral("-->P 345"), kDriveTimeoutMs);
        QTest::keyClick(window.terminal(), Qt::Key_Down); // past the newest: the (empty) line being typed
        QTRY_COMPARE_WITH_TIMEOUT(terminalLines(window).last(), QStringLiteral("-->"), kDriveTimeoutMs);
        QTest::keyClick(window.terminal(), Qt::Key_Up);
        QTRY_COMPARE_WITH_TIMEOUT(terminalLines(window).last(), QStringLiteral("-->P 345"), kDriveTimeoutMs);
        QTest::keyClick(window.terminal(), Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(endsWithLines(window, {QStringLiteral("-->P 345"),
                                                                 QStringLiteral("         345"),
                                                                 QStringLiteral("-->")}),
                                 kDriveTimeoutMs);

        // Kept for the next start, without the repeat.
        app::TerminalWidget next;
        QCOMPARE(next.history().lines(), QStringList({QStringLiteral("P 12"), QStringLiteral("P 345")}));
    }

    void historyIsCapped() {
        app::TerminalWidget terminal;
        const int extra = 7;
        for (int i = 0; i < app::CommandHistory::kCapacity + extra; ++i) {
            QTest::keyClicks(&terminal, QStringLiteral("P %1").arg(i));
            QTest::keyClick(&terminal, Qt::Key_Return);
        }
        QCOMPARE(terminal.history().lines().size(), app::CommandHistory::kCapacity);
        QCOMPARE(terminal.history().lines().first(), QStringLiteral("P %1").arg(extra));
        QCOMPARE(app::TerminalWidget().history().lines().size(), app::CommandHistory::kCapacity);
    }

    // ^X goes to the wire ahead of 95 queued commands, and the drive's own timer shows the motion ramping
    // down from the first command behind it: measured in drive time, never against the wall clock.
    void stopMotionOvertakesAQueuedTransfer() {
        // No wire pacing and the drive at a fifth of real time: queries follow each other every few ms of
        // drive time even on a busy machine, which sets how finely the stop is timed. The order on the wire
        // is the session's either way.
        serialport::SimulatorLink link(drive_core::DriveFamily::Bds5, {.speedFactor = 0.2, .lineRateLimited = false});
        Bds5Session session(link);
        QByteArray wire;
        connect(&session, &Bds5Session::rawSent, &session, [&wire](const QByteArray& b) { wire += b; });
        link.open();
        QTRY_VERIFY_WITH_TIMEOUT(session.state() == Bds5Session::State::Ready, kDriveTimeoutMs);

        QList<serialport::Bds5Response> setup;
        auto collect = [&setup](quint64, const serialport::Bds5Response& r) { setup.append(r); };
        auto c = connect(&session, &Bds5Session::finished, &session, collect);
        for (const char* line : {"PLIM OFF", "EN", "J 1000", "TMR1=60000"}) session.send(QString::fromLatin1(line));
        QTRY_COMPARE_WITH_TIMEOUT(setup.size(), 4, kDriveTimeoutMs);
        for (const auto& r : setup) QVERIFY2(r.errors.isEmpty(), qPrintable(r.command));
        disconnect(c);
        // At speed (1000 RPM, 10 ms of drive time at the power-up ACC): asked until the drive says so.
        QString vcmd;
        for (int asked = 0; asked < 200 && vcmd != QStringLiteral("1000"); ++asked) {
            QSignalSpy one(&session, &Bds5Session::finished);
            session.send(QStringLiteral("P VCMD"));
            QVERIFY(one.wait(kDriveTimeoutMs));
            vcmd = one.first().at(1).value<serialport::Bds5Response>().lines.value(0).trimmed();
        }
        QCOMPARE(vcmd, QStringLiteral("1000"));

        constexpr int kQueued = 100;
        constexpr int kStopAfter = 5;
        QList<QPair<int, int>> answers; // VCMD, TMR1 (ms, counting down) when each P ran
        qsizetype stopAt = -1;
        connect(&session, &Bds5Session::finished, &session, [&](quint64, const serialport::Bds5Response& r) {
            const QStringList values = r.lines.value(0).simplified().split(QLatin1Char(' '));
            answers.append({values.value(0).toInt(), values.value(1).toInt()});
            if (answers.size() == kStopAfter) { // the 6th P is next in the queue
                stopAt = wire.size();
                session.sendUrgent("\x18");
            }
        });
        for (int i = 0; i < kQueued; ++i) session.send(QStringLiteral("P VCMD TMR1"));
        QTRY_COMPARE_WITH_TIMEOUT(answers.size(), kQueued, 60000);

        QCOMPARE(wire.at(stopAt), '\x18');
        const QByteArray query("P VCMD TMR1\r");
        QCOMPARE(wire.left(stopAt).count(query), kStopAfter);
        QCOMPARE(wire.mid(stopAt).count(query), kQueued - kStopAfter); // all queued behind the ^X
        for (int i = 0; i < kStopAfter; ++i) QCOMPARE(answers[i].first, 1000);
        int stopped = kStopAfter;
        while (stopped < kQueued && answers[stopped].first != 0) ++stopped;
        QVERIFY(stopped < kQueued);
        for (int i = stopped; i < kQueued; ++i) QCOMPARE(answers[i].first, 0);
        // In drive time (TMR1 counts milliseconds down), whatever the machine's load: the drive read the ^X
        // before the 6th P, so from that P's time on VCMD lies on or below a ramp down from 1000 RPM at the
        // power-up DEC and AMAX of 100000 RPM/s (100 RPM a millisecond, L7571, L7560), one tick's slack.
        const int stopMs = answers[kStopAfter].second;
        for (int i = kStopAfter; i < kQueued; ++i) {
            const int sinceMs = stopMs - answers[i].second;
            const int ceiling = std::max(0, 1000 - 100 * (sinceMs - 1));
            QVERIFY2(answers[i].first <= ceiling,
                     qPrintable(QStringLiteral("answer %1: VCMD %2 %3 ms after the stop").arg(i).arg(answers[i].first).arg(sinceMs)));
        }
        qInfo("^X overtook %d queued commands; VCMD 0 %d ms of drive time after the first P behind it",
              kQueued - kStopAfter, stopMs - answers[stopped].second);
        link.close();
    }

    // The toolbar's Stop Motion in the window: ahead of queued commands, and the drive stops.
    void stopActionOvertakesQueuedCommandsInTheWindow() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        QByteArray wire;
        connect(&window.connection(), &app::DriveConnection::rawSent, &window,
                [&wire](const QByteArray& b) { wire += b; });
        QList<serialport::Bds5Response> answers;
        connect(window.connection().session(), &Bds5Session::finished, &window,
                [&answers](quint64, const serialport::Bds5Response& r) { answers.append(r); });
        for (const char* line : {"PLIM OFF", "EN", "J 500"}) window.connection().sendCommand(QString::fromLatin1(line));
        for (int i = 0; i < 20; ++i) window.connection().sendCommand(QStringLiteral("P VCMD"));
        QTRY_VERIFY_WITH_TIMEOUT(answers.size() >= 5 && answers.last().lines.value(0).trimmed() == QStringLiteral("500"),
                                 kDriveTimeoutMs);
        QVERIFY(window.driveActions().stopAction()->isEnabled());
        const qsizetype answeredBefore = answers.size(); // and one more in flight
        window.driveActions().stopAction()->trigger();
        const qsizetype stopAt = wire.indexOf('\x18');
        QCOMPARE(stopAt, wire.size() - 1); // written at once, behind nothing
        QTRY_COMPARE_WITH_TIMEOUT(answers.size(), 23, kDriveTimeoutMs * 2);
        QCOMPARE(wire.mid(stopAt).count("P VCMD\r"), 23 - answeredBefore - 1);
        QCOMPARE(answers.last().lines.value(0).trimmed(), QStringLiteral("0"));
        QVERIFY(terminalLines(window).contains(QStringLiteral("         500")));
    }

    void driveActionsFollowTheMode() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::DriveActions& drive = window.driveActions();
        QVERIFY(drive.runAction()->isEnabled());
        QVERIFY(!drive.stepAction()->isEnabled());
        QVERIFY(!drive.monitorAction()->isEnabled());
        QVERIFY(drive.enableAction()->isEnabled());

        // A program that runs until told otherwise.
        Bds5Session* session = window.connection().session();
        for (const char* line : {">BDS", "7$", "D 100", "GOTO 7", "B"}) session->send(QString::fromLatin1(line));
        session->sendEscape();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && terminalLines(window).last() == QStringLiteral("-->"),
                                 kDriveTimeoutMs);
        drive.run(7);
        QTRY_VERIFY_WITH_TIMEOUT(session->mode() == serialport::Bds5Mode::Running, kDriveTimeoutMs);
        QVERIFY(!drive.runAction()->isEnabled());
        QVERIFY(drive.monitorAction()->isEnabled());
        QVERIFY(!drive.enableAction()->isEnabled());

        drive.monitorAction()->trigger(); // Esc: monitor mode
        QTRY_VERIFY_WITH_TIMEOUT(terminalLines(window).last() == QStringLiteral("==>") && ready(window),
                                 kDriveTimeoutMs);
        QVERIFY(terminalLines(window).contains(QStringLiteral("ENTER MONITOR MODE. PUSH ESCAPE TO EXIT")));
        QVERIFY(drive.monitorAction()->text().contains(QStringLiteral("Leave")));
        QVERIFY(drive.enableAction()->isEnabled());

        drive.breakAction()->trigger(); // B at the monitor prompt: back to interactive
        QTRY_VERIFY_WITH_TIMEOUT(session->mode() == serialport::Bds5Mode::Interactive && ready(window),
                                 kDriveTimeoutMs);
        QVERIFY(drive.runAction()->isEnabled());

        // Break while running goes through the monitor prompt by itself.
        drive.run(7);
        QTRY_VERIFY_WITH_TIMEOUT(session->mode() == serialport::Bds5Mode::Running, kDriveTimeoutMs);
        drive.breakAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(session->mode() == serialport::Bds5Mode::Interactive && ready(window),
                                 kDriveTimeoutMs);
        QCOMPARE(terminalLines(window).last(), QStringLiteral("-->"));
    }

    // Issue 19: Run Label lists the labels of the program in the editor, and still takes a number only the
    // drive's program has; text that names no label keeps Run disabled and says why (it used to vanish).
    void runLabelOffersTheProgramsLabels() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        // The drive's program has 10$ and 30$; the editor's has 10$ and 20$.
        Bds5Session* session = window.connection().session();
        for (const char* line : {">BDS", "10$", "P \"AT TEN\"", "B", "30$", "P \"AT THIRTY\"", "B"})
            session->send(QString::fromLatin1(line));
        session->sendEscape();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && terminalLines(window).last() == QStringLiteral("-->"),
                                 kDriveTimeoutMs);
        window.editor()->setText(QStringLiteral("10$ ;FIRST\nP \"AT TEN\"\nB\n20$ ;SECOND\nB\nERROR$\nB\n"));

        QVERIFY(window.driveActions().runAction()->isEnabled());
        app::RunLabelDialog* dialog = window.driveActions().askRunLabel();
        QVERIFY(dialog->isVisible());
        QComboBox* combo = dialog->combo();
        QVERIFY(combo->isEditable());
        QCOMPARE(combo->count(), 2); // ERROR$ cannot be RUN
        QCOMPARE(combo->itemText(0), QStringLiteral("10$  FIRST"));
        QCOMPARE(combo->itemText(1), QStringLiteral("20$  SECOND"));
        QCOMPARE(combo->currentText(), QStringLiteral("10$  FIRST"));
        QVERIFY(dialog->runButton()->isEnabled());

        combo->lineEdit()->clear();
        QTest::keyClicks(combo->lineEdit(), QStringLiteral("TEN"));
        QVERIFY(!dialog->runButton()->isEnabled());
        QVERIFY2(dialog->note().contains(QStringLiteral("is not a label")), qPrintable(dialog->note()));
        combo->lineEdit()->clear();
        QTest::keyClicks(combo->lineEdit(), QStringLiteral("30"));
        QVERIFY(dialog->runButton()->isEnabled());
        QVERIFY2(dialog->note().contains(QStringLiteral("not in the program in the editor")),
                 qPrintable(dialog->note()));
        QTest::mouseClick(dialog->runButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(terminalLines(window).contains(QStringLiteral("AT THIRTY")), kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && session->mode() == serialport::Bds5Mode::Interactive &&
                                     terminalLines(window).last() == QStringLiteral("-->"),
                                 kDriveTimeoutMs);

        // Chosen from the list: the editor's 10$.
        dialog = window.driveActions().askRunLabel();
        dialog->combo()->setCurrentIndex(1);
        dialog->combo()->setCurrentIndex(0);
        QCOMPARE(dialog->note(), QString());
        QTest::mouseClick(dialog->runButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(terminalLines(window).contains(QStringLiteral("AT TEN")), kDriveTimeoutMs);
        QVERIFY(terminalLines(window).contains(QStringLiteral("-->RUN 10")));
    }
};

QTEST_MAIN(DriveControlTest)
#include "drive_control_test.moc"
