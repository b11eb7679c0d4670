// Motion Dialogue in the real MainWindow against the simulated SC750 (issue 8): the family's menus replace
// the BDS5's; Compile marks the first error's line; Run downloads and runs a manual example whose PRINT
// text reaches the Output window; a breakpoint stops it with its line marked; a variable is read and
// changed while stopped, and the watched ones read again at every stop; Continue resumes; Ctrl C in the editor
// stops; switching family takes the execution arrow away; ServoBASIC colours and F1 help.
#include "family_window.h"
#include "app/main_window.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_function_dialog.h"
#include "families/sc750/sc750_output_dock.h"
#include "families/sc750/sc750_setup_dialog.h"
#include "families/sc750/sc750_variables_dock.h"
#include "families/sc750/sc750_workspace.h"

#include "editor/help_popup.h"
#include "editor/program_editor.h"
#include "editor/servobasic_help.h"
#include "editor/servobasic_language.h"
#include "editor/servobasic_lexer.h"

#include <QAction>
#include <QClipboard>
#include <QDialogButtonBox>
#include <QFile>
#include <QGuiApplication>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>

#include <memory>

using app::MainWindow;
using app::Sc750Debugger;
using app::Sc750Workspace;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 20000;

QString example(const char* name) {
    return family_window::sc750Example(name);
}

bool menuVisible(const MainWindow& window, const QString& title) {
    for (QAction* a : window.menuBar()->actions())
        if (a->text() == title) return a->isVisible();
    return false;
}

using family_window::connectSc750WithProgram;
} // namespace

class Sc750WorkspaceTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskSc750WorkspaceTest"));
        QSettings().clear();
    }

    void connectingShowsMotionDialogueMenus() {
        MainWindow window;
        window.show();
        QVERIFY(window.workspace(DriveFamily::Sc750));
        QVERIFY(!menuVisible(window, QStringLiteral("&Compile")));
        QVERIFY(menuVisible(window, QStringLiteral("&Program")));
        auto& ws = family_window::connectSc750(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        QVERIFY(menuVisible(window, QStringLiteral("&Compile")));
        QVERIFY(menuVisible(window, QStringLiteral("Co&ntroller")));
        QVERIFY(!menuVisible(window, QStringLiteral("&Program")));
        QCOMPARE(ws.action(QStringLiteral("Run Program"))->shortcut(), QKeySequence(QStringLiteral("Ctrl+R")));
        QCOMPARE(ws.action(QStringLiteral("Reset Program"))->shortcut(), QKeySequence(QStringLiteral("Alt+R")));
        QCOMPARE(ws.action(QStringLiteral("Continue Program"))->shortcut(), QKeySequence(Qt::Key_F5));
        QCOMPARE(ws.action(QStringLiteral("Output Window"))->shortcut(), QKeySequence(Qt::Key_F4));
        QCOMPARE(ws.action(QStringLiteral("Set Breakpoint"))->shortcut(), QKeySequence(Qt::Key_F9));
        QTRY_VERIFY_WITH_TIMEOUT(ws.statusText().contains(QStringLiteral("SC752")), kTimeoutMs);
        // The toolbar is Motion Dialogue's: the BDS5's Run Label and Kill are gone, not left as empty strips.
        const QStringList sc750Buttons{QStringLiteral("Compile Program"), QStringLiteral("Run Program"),
                                       QStringLiteral("Stop"), QStringLiteral("Continue Program"),
                                       QStringLiteral("Set Breakpoint")};
        QCOMPARE(family_window::toolBarButtons(window), sc750Buttons);
        QVERIFY(ws.action(QStringLiteral("Run Program"))->isEnabled());
        // Back to the BDS5: the Program menu returns, ours go.
        window.connectDrive(app::ConnectionChoice::simulator(DriveFamily::Bds5));
        QVERIFY(!ws.isConnected());
        QVERIFY(!menuVisible(window, QStringLiteral("&Compile")));
        QVERIFY(menuVisible(window, QStringLiteral("&Program")));
        const QStringList bds5Buttons = family_window::toolBarButtons(window);
        QVERIFY2(bds5Buttons.contains(QStringLiteral("Run Label")), qPrintable(bds5Buttons.join(QLatin1Char(','))));
        QVERIFY(!bds5Buttons.contains(QStringLiteral("Compile Program")));
    }

    void compileErrorMarksItsLine() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window, QStringLiteral("DIM a AS INTEGER\na = 1\nGOTO Nowhere\nEND\n"));
        QVERIFY(!ws.debugger().compile());
        QVERIFY2(ws.debugger().lastError().startsWith(QStringLiteral("LINE 3 ")),
                 qPrintable(ws.debugger().lastError()));
        int line = 0, index = 0;
        window.editor()->getCursorPosition(&line, &index);
        QCOMPARE(line, 2);
        QVERIFY(window.editor()->markersAtLine(2) & (1 << Sc750Debugger::kErrorMarker));
        QVERIFY(window.editor()->annotation(2).contains(QStringLiteral("Col ")));
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("Compile error")));
        // Fixed, it compiles and the mark goes.
        window.editor()->setText(QStringLiteral("DIM a AS INTEGER\na = 1\nEND\n"));
        QVERIFY(ws.debugger().compile());
        QCOMPARE(window.editor()->markerFindNext(0, 1 << Sc750Debugger::kErrorMarker), -1);
    }

    void runBreakpointVariablesContinue() {
        MainWindow window;
        window.show();
        // 02-loop-again.bas (L1134-L1136): PRINT "All work and no play" forever.
        const QString program = example("02-loop-again.bas");
        QVERIFY(!program.isEmpty());
        Sc750Workspace& ws = connectSc750WithProgram(window, program);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        // A breakpoint on the PRINT line (2), set before running (L2706).
        window.editor()->setCursorPosition(1, 4);
        ws.action(QStringLiteral("Set Breakpoint"))->trigger();
        QCOMPARE(ws.debugger().breakpointLines(), QList<int>{2});
        QSignalSpy started(&ws.debugger(), &Sc750Debugger::runStarted);
        ws.action(QStringLiteral("Run Program"))->trigger();       // compiles first: never compiled
        QTRY_COMPARE_WITH_TIMEOUT(started.count(), 1, kTimeoutMs); // downloaded, R answered
        QVERIFY(ws.outputDock()->isVisible());
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::AtBreakpoint, kTimeoutMs);
        QCOMPARE(ws.debugger().currentLine(), 1);
        QVERIFY(window.editor()->markersAtLine(1) & (1 << Sc750Debugger::kCurrentLineMarker));
        QVERIFY(ws.statusText().contains(QStringLiteral("At breakpoint")));
        // Continue: one PRINT, and the breakpoint again.
        ws.action(QStringLiteral("Continue Program"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(ws.outputDock()->text().contains(QStringLiteral("All work and no play")), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::AtBreakpoint, kTimeoutMs);
        QCOMPARE(ws.outputDock()->text().count(QStringLiteral("All work")), 1);

        // Variables while stopped: read, write, read back.
        app::Sc750VariablesDock* vars = ws.variablesDock();
        vars->readVariable(QStringLiteral("RUN.SPEED"));
        QTRY_VERIFY_WITH_TIMEOUT(!vars->value(QStringLiteral("RUN.SPEED")).isEmpty(), kTimeoutMs);
        vars->writeVariable(QStringLiteral("RUN.SPEED"), QStringLiteral("250"));
        QTRY_COMPARE_WITH_TIMEOUT(vars->value(QStringLiteral("RUN.SPEED")), QStringLiteral("250"), kTimeoutMs);
        vars->readVariable(QStringLiteral("run.speed"));
        QTRY_VERIFY_WITH_TIMEOUT(vars->lastMessage().contains(QStringLiteral("read")), kTimeoutMs);
        QCOMPARE(vars->value(QStringLiteral("RUN.SPEED")), QStringLiteral("250"));
        QCOMPARE(vars->table()->rowCount(), 1);

        // Continue resumes: one more PRINT and the breakpoint again.
        ws.action(QStringLiteral("Continue Program"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(ws.outputDock()->text().count(QStringLiteral("All work")), 2, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::AtBreakpoint, kTimeoutMs);

        // Reset: back to the top, not running.
        ws.action(QStringLiteral("Reset Program"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Loaded, kTimeoutMs);
    }

    void ctrlCInTheEditorStops() {
        // PRINT with PAUSE: slower than the wire, so the controller's answers are not queued behind output.
        // (02-loop-again prints faster than 9600 baud carries; the simulated SC750 then queues the excess
        // ahead of its answers, and a stop is acknowledged only after it has all gone out.)
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window, QStringLiteral("PAUSE.TIME = 0.05\nTick:\n  PRINT \"tick\"\n  PAUSE\n"
                                                                 "GOTO Tick\n"));
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        ws.debugger().run();
        QTRY_VERIFY_WITH_TIMEOUT(ws.outputDock()->text().count(QStringLiteral("tick")) >= 3, kTimeoutMs);
        QCOMPARE(ws.debugger().state(), Sc750Debugger::State::Running);
        window.activateWindow();
        window.editor()->setFocus();
        window.editor()->selectAll();
        QTest::keyClick(window.editor(), Qt::Key_C, Qt::ControlModifier); // a selection: Copy, not Stop
        QVERIFY(QGuiApplication::clipboard()->text().contains(QStringLiteral("GOTO Tick")));
        // Still running: three more ticks come, and the debugger never left Running.
        const qsizetype ticks = ws.outputDock()->text().count(QStringLiteral("tick"));
        QTRY_VERIFY_WITH_TIMEOUT(ws.outputDock()->text().count(QStringLiteral("tick")) >= ticks + 3, kTimeoutMs);
        QCOMPARE(ws.debugger().state(), Sc750Debugger::State::Running);
        window.editor()->setCursorPosition(0, 0);
        QTest::keyClick(window.editor(), Qt::Key_C, Qt::ControlModifier); // L2692
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Stopped, kTimeoutMs);
        QVERIFY(ws.debugger().currentLine() >= 0);
        ws.action(QStringLiteral("Continue Program"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Running, kTimeoutMs);
        ws.action(QStringLiteral("Stop Program"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Stopped, kTimeoutMs);
    }

    void breakpointSetBeforeRunIsHit() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window, QStringLiteral("DIM Count AS INTEGER\nCount = 41\nCount = Count + 1\n"
                                                                 "PRINT \"Count is\"; Count\nEND\n"));
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        ws.debugger().toggleBreakpointAt(*window.editor(), 3); // the PRINT
        ws.debugger().run();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::AtBreakpoint, kTimeoutMs);
        QCOMPARE(ws.debugger().currentLine(), 3);
        ws.variablesDock()->readVariable(QStringLiteral("Count"));
        QTRY_COMPARE_WITH_TIMEOUT(ws.variablesDock()->value(QStringLiteral("COUNT")), QStringLiteral("42"), kTimeoutMs);
        ws.variablesDock()->writeVariable(QStringLiteral("Count"), QStringLiteral("7"));
        QTRY_COMPARE_WITH_TIMEOUT(ws.variablesDock()->value(QStringLiteral("COUNT")), QStringLiteral("7"), kTimeoutMs);
        ws.debugger().continueProgram();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::Ended, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(ws.outputDock()->text().contains(QStringLiteral("Count is 7")), kTimeoutMs);
    }

    // Issue 19: the watch list is read again whenever the program stops, so at a breakpoint it shows the
    // controller's values there, not those read before the program ran.
    void watchedValuesAreReadAtEachBreakpoint() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window, QStringLiteral("DIM Count AS INTEGER\nCount = 0\nAgain:\n"
                                                                 "Count = Count + 1\nPRINT \"Count is\"; Count\n"
                                                                 "GOTO Again\n"));
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        app::Sc750VariablesDock* vars = ws.variablesDock();
        // Watched before the program is on the controller, which does not know COUNT yet.
        vars->readVariable(QStringLiteral("Count"));
        QTRY_VERIFY_WITH_TIMEOUT(vars->lastMessage().startsWith(QStringLiteral("COUNT: ")), kTimeoutMs);
        QCOMPARE(vars->value(QStringLiteral("COUNT")), QString());
        ws.debugger().toggleBreakpointAt(*window.editor(), 4); // the PRINT
        ws.debugger().run();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::AtBreakpoint, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(vars->value(QStringLiteral("COUNT")), QStringLiteral("1"), kTimeoutMs);
        // Continue: one pass of the loop, the breakpoint again, and the watch follows without a Refresh.
        ws.debugger().continueProgram();
        QTRY_VERIFY_WITH_TIMEOUT(ws.outputDock()->text().contains(QStringLiteral("Count is 1")), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(vars->value(QStringLiteral("COUNT")), QStringLiteral("2"), kTimeoutMs);
        QCOMPARE(ws.debugger().state(), Sc750Debugger::State::AtBreakpoint);
        QCOMPARE(vars->table()->rowCount(), 1);
    }

    // Issue 19: the execution arrow belongs to the SC750's session. Switching to the PMC-960 while the program
    // is stopped at a breakpoint takes it, and the current-line band, out of the editor the PMC-960 then
    // shows; the user's breakpoint stays.
    void switchingFamilyClearsTheExecutionArrow() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window, QStringLiteral("DIM Count AS INTEGER\nCount = 41\n"
                                                                 "PRINT \"Count is\"; Count\nEND\n"));
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        editor::ProgramEditor* program = window.editor();
        ws.debugger().toggleBreakpointAt(*program, 2); // the PRINT
        ws.debugger().run();
        QTRY_COMPARE_WITH_TIMEOUT(ws.debugger().state(), Sc750Debugger::State::AtBreakpoint, kTimeoutMs);
        const int arrow = (1 << Sc750Debugger::kArrowMarker) | (1 << Sc750Debugger::kCurrentLineMarker);
        QCOMPARE(program->markerFindNext(0, arrow), 2);

        window.connectDrive(app::ConnectionChoice::simulator(DriveFamily::Pmc960));
        QCOMPARE(window.activeFamily(), DriveFamily::Pmc960);
        QCOMPARE(window.editor(), program); // the PMC-960 shows the same tab
        QCOMPARE(program->markerFindNext(0, arrow), -1);
        QCOMPARE(ws.debugger().currentLine(), -1);
        QCOMPARE(program->markerFindNext(0, 1 << Sc750Debugger::kBreakpointMarker), 2);
    }

    void controllerSetUpAndUnconfigure() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window, QStringLiteral("PRINT \"hi\"\nEND\n"));
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        auto* menu = qobject_cast<app::Sc750ControllerMenu*>(ws.menus().at(1));
        auto configured = [&ws] {
            auto flag = std::make_shared<QString>();
            ws.send('?', {},
                    [flag](const serialport::Sc750Reply& r) { *flag = r.payload.section(QLatin1Char(','), 4, 4); });
            if (!QTest::qWaitFor([flag] { return !flag->isEmpty(); }, kTimeoutMs)) return QStringLiteral("no answer");
            return *flag;
        };

        // Unconfigure: OK on the question, then "Yes" typed (L2580-L2591).
        auto* question = qobject_cast<QMessageBox*>(menu->unconfigure());
        QVERIFY(question);
        question->button(QMessageBox::Ok)->click();
        QDialog* confirm = nullptr;
        QTRY_VERIFY((confirm = window.findChild<QDialog*>(QStringLiteral("sc750UnconfigureDialog"))));
        auto* buttons = confirm->findChild<QDialogButtonBox*>();
        confirm->findChild<QLineEdit*>()->setText(QStringLiteral("yes"));
        QVERIFY(!buttons->button(QDialogButtonBox::Ok)->isEnabled());
        confirm->findChild<QLineEdit*>()->setText(QStringLiteral("Yes"));
        buttons->button(QDialogButtonBox::Ok)->click();
        QTRY_COMPARE_WITH_TIMEOUT(configured(), QStringLiteral("0"), kTimeoutMs);

        // Controller Set Up, Auto, Gentle: the PARAMS block goes into the program, the controller is configured.
        auto* setup = qobject_cast<app::Sc750SetupDialog*>(menu->controllerSetUp());
        QVERIFY(setup);
        // Auto follows the motor: two motors of the table give two PARAMS blocks (catalog::setupParameters).
        setup->setMotorPart(QStringLiteral("R45G"));
        const QString medium = setup->paramsBlock();
        QVERIFY(medium.contains(QStringLiteral("ILC = 59\n")));
        // The manual's own PARAMS block for this motor (L2505-2525): reals with six decimals.
        QVERIFY2(medium.contains(QStringLiteral("SIX.THRESH = 3147.836538\n")), qPrintable(medium));
        QVERIFY(medium.contains(QStringLiteral("SIG.THRESH = 2833.052885\n")));
        QVERIFY(medium.contains(QStringLiteral("POLECOUNT = 4\n")));
        QVERIFY(setup->status().contains(QStringLiteral("R45G")));
        setup->setMotorPart(QStringLiteral("R63G"));
        QVERIFY(setup->paramsBlock() != medium);
        QVERIFY(setup->paramsBlock().contains(QStringLiteral("POLECOUNT = 6\n")));
        QTRY_COMPARE_WITH_TIMEOUT(setup->controllerModel(), 752, kTimeoutMs); // read over the wire
        setup->setMotorPart(QString());
        setup->setGentle(true);
        QVERIFY(setup->paramsBlock().contains(QStringLiteral("KVP = 0.043543")));
        QVERIFY(setup->paramsBlock().contains(QStringLiteral("ARF0 = 100")));
        setup->apply();
        QVERIFY(window.editor()->text().startsWith(QStringLiteral("'-----Parameter Values Header-----\nPARAMS START")));
        QVERIFY(window.editor()->text().endsWith(QStringLiteral("PRINT \"hi\"\nEND\n")));
        QVERIFY(ws.debugger().compile());
        QTRY_COMPARE_WITH_TIMEOUT(configured(), QStringLiteral("1"), kTimeoutMs);
        ws.variablesDock()->readVariable(QStringLiteral("KVP"));
        QTRY_COMPARE_WITH_TIMEOUT(ws.variablesDock()->value(QStringLiteral("KVP")), QStringLiteral(".043543"),
                                  kTimeoutMs);

        // Edit Parameters: Manual, holding the program's values.
        auto* edit = qobject_cast<app::Sc750SetupDialog*>(menu->editParameters());
        QVERIFY(edit);
        QVERIFY(edit->paramsBlock().contains(QStringLiteral("KVP = 0.043543")));
        QVERIFY(edit->table()->item(0, 1)->flags() & Qt::ItemIsEditable);
        edit->close();
    }

    // Compile > Real Time Function Call (L2796-L2812): GO.VEL with a RUN.SPEED typed in the dialog reaches
    // the controller, and the simulated motor turns at that speed.
    void realTimeFunctionCallTurnsTheMotor() {
        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        bool enabled = false;
        ws.send('P', QStringLiteral("ENABLE=1"), [&enabled](const serialport::Sc750Reply&) { enabled = true; });
        QTRY_VERIFY_WITH_TIMEOUT(enabled, kTimeoutMs);
        auto* dialog = qobject_cast<app::Sc750FunctionDialog*>(ws.showFunctionCall());
        QVERIFY(dialog);
        dialog->selectFunction(QStringLiteral("GO.VEL"));
        QVERIFY(dialog->field(QStringLiteral("RUN.SPEED")));
        QTRY_COMPARE_WITH_TIMEOUT(dialog->field(QStringLiteral("RUN.SPEED"))->text(), QStringLiteral("1000"),
                                  kTimeoutMs);
        dialog->field(QStringLiteral("RUN.SPEED"))->setText(QStringLiteral("600"));
        QSignalSpy called(dialog, &app::Sc750FunctionDialog::called);
        dialog->call();
        QTRY_COMPARE_WITH_TIMEOUT(called.count(), 1, kTimeoutMs);
        QCOMPARE(dialog->status(), QStringLiteral("GO.VEL issued."));
        QTRY_VERIFY_WITH_TIMEOUT((ws.variablesDock()->readVariable(QStringLiteral("VELOCITY")),
                                  ws.variablesDock()->value(QStringLiteral("VELOCITY")) == QStringLiteral("600")),
                                 kTimeoutMs);
        ws.variablesDock()->readVariable(QStringLiteral("RUN.SPEED"));
        QTRY_COMPARE_WITH_TIMEOUT(ws.variablesDock()->value(QStringLiteral("RUN.SPEED")), QStringLiteral("600"),
                                  kTimeoutMs);
        dialog->selectFunction(QStringLiteral("ABORT.MOTION"));
        dialog->call();
        QTRY_COMPARE_WITH_TIMEOUT(called.count(), 2, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT((ws.variablesDock()->readVariable(QStringLiteral("VELOCITY")),
                                  ws.variablesDock()->value(QStringLiteral("VELOCITY")) == QStringLiteral("0")),
                                 kTimeoutMs);

        // Controller > Axis Selection: the address goes to the workspace and the status bar.
        ws.action(QStringLiteral("Axis Selection"))->trigger();
        QInputDialog* axis = nullptr;
        QTRY_VERIFY((axis = window.findChild<QInputDialog*>()));
        QCOMPARE(axis->intValue(), 255);
        axis->setIntValue(3);
        axis->accept();
        QCOMPARE(ws.axis(), 3);
        auto* label = window.statusBar()->findChild<QLabel*>(QStringLiteral("sc750CursorLabel"));
        QVERIFY(label);
        QVERIFY2(label->text().startsWith(QStringLiteral("Axis 003 ")), qPrintable(label->text()));
        // The simulated controller is an RS-232 unit (S1 = 255): it ignores the logon and still answers.
        QString model;
        ws.send('G', QStringLiteral("MODEL"), [&model](const serialport::Sc750Reply& r) { model = r.payload; });
        QTRY_COMPARE_WITH_TIMEOUT(model, QStringLiteral("MODEL=752"), kTimeoutMs);
    }

    void sourceFileDownloadAndUpload() {
        MainWindow window;
        window.show();
        // Longer than one 64-byte chunk, with the manual's typographic quotes (UTF-8 in the editor).
        const QString program = example("03-time-wait.bas") + QStringLiteral("\u2018 comment\n").repeated(20);
        Sc750Workspace& ws = connectSc750WithProgram(window, program);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        auto* menu = qobject_cast<app::Sc750ControllerMenu*>(ws.menus().at(1));
        menu->downloadSource();
        QTRY_VERIFY_WITH_TIMEOUT(window.statusBar()->currentMessage().contains(QStringLiteral("Source stored")),
                                 kTimeoutMs);
        auto* first = window.editor();
        menu->uploadSource();
        QTRY_VERIFY_WITH_TIMEOUT(window.editor() != first, kTimeoutMs);
        QCOMPARE(window.editor()->text(), program);
        QVERIFY(editor::ServoBasicLanguage::of(window.editor())); // a .bas tab
    }

    void servoBasicEditing() {
        QCOMPARE(editor::servoBasicWordStyle("go.vel"), editor::BasicKeyword);
        QCOMPARE(editor::servoBasicWordStyle("RUN.SPEED"), editor::BasicVariable);
        QCOMPARE(editor::servoBasicWordStyle("Loop_Again"), editor::BasicDefault);
        const QByteArray styles = editor::styleServoBasicLine("Loop_Again: PRINT \"x\" ' note");
        QCOMPARE(styles[0], char(editor::BasicLabel));
        QCOMPARE(styles[12], char(editor::BasicKeyword));
        QCOMPARE(styles[18], char(editor::BasicString));
        QCOMPARE(styles[styles.size() - 1], char(editor::BasicComment));
        QVERIFY(editor::servoBasicHelpHtml(QStringLiteral("GO.VEL")).contains(QStringLiteral("GO.VEL")));

        MainWindow window;
        window.show();
        Sc750Workspace& ws = connectSc750WithProgram(window);
        QVERIFY(window.editor()->text().contains(QStringLiteral("PARAMS START")));
        QVERIFY(ws.debugger().compile()); // the boiler-plate compiles as it is
        auto* language = editor::ServoBasicLanguage::of(window.editor());
        QVERIFY(language);
        QVERIFY(qobject_cast<editor::ServoBasicLexer*>(window.editor()->lexer()));
        window.editor()->setText(QStringLiteral("GO.VEL\n"));
        window.editor()->setCursorPosition(0, 3);
        QCOMPARE(language->showHelpAtCursor(), QStringLiteral("GO.VEL"));
        QVERIFY(language->helpPopup()->isVisible());
        // Completion from the catalog: "GO.V" offers GO.VEL.
        window.editor()->setText(QStringLiteral("go.v"));
        window.editor()->setCursorPosition(0, 4);
        QVERIFY(language->showCompletions(true));
        QVERIFY(window.editor()->isListActive());
        window.editor()->SendScintilla(QsciScintilla::SCI_AUTOCCOMPLETE);
        QCOMPARE(window.editor()->text(), QStringLiteral("GO.VEL"));
        window.editor()->setText(QStringLiteral("GO.VEL\n"));
        window.editor()->setCursorPosition(0, 3);
        auto* label = window.statusBar()->findChild<QLabel*>(QStringLiteral("sc750CursorLabel"));
        QVERIFY(label);
        QTRY_COMPARE(label->text(), QStringLiteral("Axis 255  Line 0001 Col 04")); // updated on Scintilla's UI update

        // At most ten breakpoints (L2706), in the margin of an editor whose program is not on the drive.
        window.editor()->setText(QStringLiteral("PRINT 1\n").repeated(15));
        for (int line = 0; line < 12; ++line) ws.debugger().toggleBreakpointAt(*window.editor(), line);
        QCOMPARE(ws.debugger().breakpointLines().size(), Sc750Debugger::kMaxBreakpoints);
        ws.action(QStringLiteral("Clear All Breakpoints"))->trigger();
        QVERIFY(ws.debugger().breakpointLines().isEmpty());
    }
};

QTEST_MAIN(Sc750WorkspaceTest)
#include "sc750_workspace_test.moc"
