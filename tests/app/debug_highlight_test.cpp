// Beyond Motion Link: while the drive single-steps or traces the manual's nested-IF example 55$ (X1=X2=1),
// the editor highlights exactly the lines of the manual's trace (L5688-5699), and the mark goes when another
// family is chosen. Also the pieces: the stream parser and the line matching.
#include "app_test_support.h"
#include "families/bds5/debug_highlighter.h"
#include "families/bds5/drive_actions.h"
#include "families/bds5/drive_connection.h"
#include "app/drive/line_locator.h"
#include "app/main_window.h"
#include "families/bds5/step_trace_parser.h"
#include "app/drive/terminal_widget.h"

#include "editor/program_editor.h"
#include "serialport/bds5_session.h"

#include <QAction>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;

// spec/examples/bds5/29-nested-if-55.bds (L4074-4088), as the user has it in the editor.
const QStringList kProgram{QStringLiteral("55$"),
                           QStringLiteral("IF X1 GT 0"),
                           QStringLiteral("  IF X2 GT 0"),
                           QStringLiteral("    P \"BOTH X1 AND X2 > 0\""),
                           QStringLiteral("  ELSE"),
                           QStringLiteral("    P \"ONLY X1 GT 0\""),
                           QStringLiteral("  ENDIF"),
                           QStringLiteral("ELSE"),
                           QStringLiteral("  IF X2 GT 0"),
                           QStringLiteral("    P \"ONLY X2 GT 0\""),
                           QStringLiteral("  ELSE"),
                           QStringLiteral("    P \"NEITHER X1 NOR X2 > 0\""),
                           QStringLiteral("  ENDIF"),
                           QStringLiteral("ENDIF"),
                           QStringLiteral("B")};
// The manual's trace: 55$, IF X1 GT 0, IF X2 GT 0, P "BOTH...", ELSE, ENDIF, ELSE, ENDIF, B.
const QList<int> kTraced{0, 1, 2, 3, 4, 6, 7, 13, 14};

bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}
QString lastTerminalLine(const MainWindow& window) {
    return window.terminal()->text().split(QLatin1Char('\n')).last();
}
// The line the user sees marked in the editor, -1 for none.
int markedLine(const MainWindow& window) {
    const int mask = 1 << app::DebugHighlighter::kLineMarker;
    return window.editor()->markerFindNext(0, mask);
}

// The program onto the drive the way a terminal user would: >BDS, the lines, Esc; then X1=X2=1.
void loadProgram(MainWindow& window, const QStringList& extra) {
    window.editor()->setText(kProgram.join(QLatin1Char('\n')) + QLatin1Char('\n'));
    auto* session = window.connection().session();
    session->send(QStringLiteral(">BDS"));
    for (const QString& line : kProgram) session->send(line);
    session->sendEscape();
    for (const QString& line : QStringList{QStringLiteral("X1=1"), QStringLiteral("X2=1")} + extra)
        session->send(line);
}
} // namespace

class DebugHighlightTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskDebugHighlightTest"));
        QSettings().clear();
    }

    void parserFindsStepLinesTraceLinesAndRun() {
        // What the simulated drive sent in a session, cut into odd pieces.
        const QByteArray stream =
            "-->RUN 55\r\n55$\r\ns-->\r\nIF X1 GT 0\r\ns-->P X1\r\n           1\r\ns-->\r\n  IF X2 GT 0\r\n"
            "s-->SS OFF\r\nBOTH X1 AND X2 > 0\r\n-->TRC ON\r\n-->RUN\r\nt...55$\r\nt.A.  ELSE\r\n"
            "BOTH X1 AND X2 > 0\r\nAt.B\r\n\r\nENTER MONITOR MODE. PUSH ESCAPE TO EXIT\r\n==>";
        app::StepTraceParser parser;
        std::vector<app::StepTraceParser::Event> events;
        for (qsizetype at = 0; at < stream.size(); at += 7)
            for (auto& e : parser.feed(stream.mid(at, 7))) events.push_back(e);
        using Kind = app::StepTraceParser::Event::Kind;
        QStringList seen;
        for (const auto& e : events) {
            switch (e.kind) {
            case Kind::Started: seen << QStringLiteral("run %1").arg(e.label); break;
            case Kind::AboutToRun: seen << (e.stepping ? QStringLiteral("step ") : QStringLiteral("trace ")) + e.text; break;
            case Kind::Paused: seen << QStringLiteral("paused"); break;
            case Kind::Ended: seen << QStringLiteral("ended"); break;
            }
        }
        QCOMPARE(seen, QStringList({"ended", "run 55", "step 55$", "step IF X1 GT 0", "step   IF X2 GT 0",
                                    "ended", "ended", "run -1", "trace 55$", "trace   ELSE", "trace B",
                                    "paused"}));
    }

    void locatorPrefersTheSameIndentationAndTheNextOccurrence() {
        const QStringList traced{QStringLiteral("55$"), QStringLiteral("IF X1 GT 0"), QStringLiteral("  IF X2 GT 0"),
                                 QStringLiteral("    P \"BOTH X1 AND X2 > 0\""), QStringLiteral("  ELSE"),
                                 QStringLiteral("  ENDIF"), QStringLiteral("ELSE"), QStringLiteral("ENDIF"),
                                 QStringLiteral("B")};
        QList<int> found;
        int at = app::LineLocator::labelLine(kProgram, 55) - 1;
        for (const QString& text : traced) found << (at = app::LineLocator::find(kProgram, text, at));
        QCOMPARE(found, kTraced);
        // A drive that lost indentation and comments still finds the line, the next one first.
        const QStringList commented{QStringLiteral("10$ ; start"), QStringLiteral("\tELSE ; one"),
                                    QStringLiteral("ELSE;not a comment"), QStringLiteral("ELSE ; two")};
        QCOMPARE(app::LineLocator::find(commented, QStringLiteral("ELSE"), 1), 3);
        QCOMPARE(app::LineLocator::find(commented, QStringLiteral("else"), 3), 3); // same indentation wins
        QCOMPARE(app::LineLocator::find(commented, QStringLiteral("  ELSE"), 1), 3);
        QCOMPARE(app::LineLocator::find(commented, QStringLiteral("  ELSE"), 3), 1);
        QCOMPARE(app::LineLocator::labelLine(commented, 10), 0);
        QCOMPARE(app::LineLocator::find(commented, QStringLiteral("GOTO 5"), 0), -1);
    }

    void singleStepHighlightsTheLinesOf55() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        loadProgram(window, {QStringLiteral("SS ON")});
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && lastTerminalLine(window) == QStringLiteral("-->"), kDriveTimeoutMs);
        QCOMPARE(markedLine(window), -1);

        app::DriveActions& drive = window.driveActions();
        drive.run(55);
        for (const int expected : kTraced) {
            QTRY_VERIFY_WITH_TIMEOUT(lastTerminalLine(window) == QStringLiteral("s-->") && ready(window),
                                     kDriveTimeoutMs);
            QTRY_COMPARE_WITH_TIMEOUT(markedLine(window), expected, kDriveTimeoutMs);
            QCOMPARE(window.debugHighlighter().currentLine(), expected);
            QVERIFY(drive.stepAction()->isEnabled());
            if (expected == 3) { // a monitor command at the step prompt leaves the mark where it is
                QTest::keyClicks(window.terminal(), QStringLiteral("P X1"));
                QTest::keyClick(window.terminal(), Qt::Key_Return);
                QTRY_VERIFY_WITH_TIMEOUT(window.terminal()->text().endsWith(QStringLiteral("s-->P X1\n           1\ns-->")),
                                         kDriveTimeoutMs);
                // Once the session has taken the prompt (what would move the mark), the mark is still on 3.
                QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
                QCOMPARE(markedLine(window), 3);
            }
            drive.stepAction()->trigger();
        }
        // B ran: the drive is back at -->, nothing is about to run.
        QTRY_VERIFY_WITH_TIMEOUT(lastTerminalLine(window) == QStringLiteral("-->") && ready(window), kDriveTimeoutMs);
        QCOMPARE(markedLine(window), -1);
        QVERIFY(window.terminal()->text().contains(QStringLiteral("BOTH X1 AND X2 > 0")));
    }

    // Issue 19: the step mark is the BDS5 session's. Switching to the PMC-960 at the step prompt takes it out
    // of the editor, which the PMC-960 then shows (and whose marker numbers the SC750's debugger shares).
    void switchingFamilyClearsTheStepMark() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        loadProgram(window, {QStringLiteral("SS ON")});
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && lastTerminalLine(window) == QStringLiteral("-->"), kDriveTimeoutMs);
        window.driveActions().run(55);
        QTRY_COMPARE_WITH_TIMEOUT(markedLine(window), 0, kDriveTimeoutMs);
        const auto* program = window.editor();

        window.connectDrive(app::ConnectionChoice::simulator(drive_core::DriveFamily::Pmc960));
        QCOMPARE(window.editor(), program);
        QCOMPARE(markedLine(window), -1);
        QCOMPARE(window.editor()->markerFindNext(0, 1 << app::DebugHighlighter::kArrowMarker), -1);
        QCOMPARE(window.debugHighlighter().currentLine(), -1);
    }

    void traceHighlightsTheManualsTraceAndContinueRunsOn() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        loadProgram(window, {QStringLiteral("TRC ON")});
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && lastTerminalLine(window) == QStringLiteral("-->"), kDriveTimeoutMs);
        QSignalSpy marked(&window.debugHighlighter(), &app::DebugHighlighter::lineHighlighted);
        window.driveActions().run(55);
        QTRY_VERIFY_WITH_TIMEOUT(window.terminal()->text().endsWith(QStringLiteral("t...B\n-->")), kDriveTimeoutMs);
        QList<int> lines;
        for (const QList<QVariant>& args : marked) lines << args.at(0).toInt();
        QCOMPARE(lines, kTraced);

        // Single-step, then Continue (SS OFF): the program runs to its end and the mark goes.
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        window.connection().sendCommand(QStringLiteral("TRC OFF"));
        window.driveActions().singleStepAction()->trigger();
        QVERIFY(window.driveActions().singleStepAction()->isChecked());
        window.driveActions().run(55);
        QTRY_VERIFY2_WITH_TIMEOUT(lastTerminalLine(window) == QStringLiteral("s-->"), qPrintable(window.terminal()->text()),
                                  kDriveTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(markedLine(window), 0, kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(window.driveActions().continueAction()->isEnabled(), kDriveTimeoutMs);
        window.driveActions().continueAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(window.terminal()->text().endsWith(QStringLiteral("BOTH X1 AND X2 > 0\n-->")),
                                 kDriveTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(markedLine(window), -1, kDriveTimeoutMs);
        QVERIFY(!window.driveActions().singleStepAction()->isChecked());
    }
};

QTEST_MAIN(DebugHighlightTest)
#include "debug_highlight_test.moc"
