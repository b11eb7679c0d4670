// The PMC-960 workspace in the real MainWindow against the simulated controller (issue 9): the MPL menu
// replaces the BDS5's; a manual example downloads with its checksum verified and uploads unchanged; a
// program too big for the buffer gets the controller's #C1 with its line; the status panel follows a move;
// the parameter table shows stored vs in-use values and an edit reaches the controller; .mpl tabs use MPL;
// Stop during a download cancels it; MPL > Run Routine lists the editor's labels and runs one, enabling the
// servo first if asked, and a refusal says the program in the drive may differ; the status panel follows a
// running routine, and an error inside one names the failing command and its line (issue 19).
#include "family_window.h"
#include "app/drive/terminal_widget.h"
#include "app/errors/error_log_dock.h"
#include "app/errors/error_source.h"
#include "app/main_window.h"
#include "editor/mpl_language.h"
#include "variables/variable_browser.h"
#include "variables/variable_model.h"
#include "variables/variable_sync.h"

#include <QDockWidget>
#include <QPushButton>
#include <QTreeView>
#include "families/pmc960/pmc960_program_transfer.h"
#include "families/pmc960/pmc960_routine_runner.h"
#include "families/pmc960/pmc960_run_dialog.h"
#include "families/pmc960/pmc960_status_dock.h"
#include "families/pmc960/pmc960_workspace.h"

#include "drive_core/catalog/pmc960_catalog.h"
#include "editor/help_popup.h"
#include "editor/mpl_lexer.h"
#include "editor/program_editor.h"
#include "document_controller.h"
#include "editor_area.h"
#include "editor_tabs.h"
#include "resources/resources.h"

#include <QAction>
#include <QCheckBox>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using app::MainWindow;
using app::Pmc960Workspace;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 20000;
constexpr int kRunTimeoutMs = 30000; // a routine that moves runs in the simulator's real time

QString example(const char* name) {
    QFile file(QStringLiteral(PMC960_EXAMPLES "/") + QLatin1String(name));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

bool menuVisible(const MainWindow& window, const QString& title) {
    for (QAction* a : window.menuBar()->actions())
        if (a->text() == title) return a->isVisible();
    return false;
}

using family_window::connectPmc960;

editor::ProgramEditor* newMplTab(MainWindow& window, const QString& name, const QString& text) {
    editor::ProgramEditor* e = window.editorArea()->tabs()->addEditor(name);
    e->setText(text);
    return e;
}

// MPL > Download Program for the current tab; true once the controller's checksum matched.
bool downloadCurrentTab(Pmc960Workspace& ws) {
    QSignalSpy downloaded(&ws.transfer(), &app::Pmc960ProgramTransfer::downloadFinished);
    ws.action(QStringLiteral("Download Program"))->trigger();
    if (!QTest::qWaitFor([&] { return downloaded.count() == 1; }, kTimeoutMs)) return false;
    return downloaded.at(0).at(0).value<serialport::Pmc960DownloadResult>().ok;
}

// MPL > Run Routine, as the user opens it: the dialog that appears.
app::Pmc960RunDialog* openRunRoutine(MainWindow& window, Pmc960Workspace& ws) {
    QAction* run = ws.action(QStringLiteral("Run Routine"));
    if (!run || !run->isEnabled()) return nullptr;
    run->trigger();
    auto* dialog = window.findChild<app::Pmc960RunDialog*>();
    return dialog && QTest::qWaitForWindowExposed(dialog) ? dialog : nullptr;
}

QStringList itemTexts(const QListWidget* list) {
    QStringList texts;
    for (int i = 0; i < list->count(); ++i) texts << list->item(i)->text();
    return texts;
}
} // namespace

class Pmc960WorkspaceTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskPmc960WorkspaceTest"));
        QSettings().clear();
        qRegisterMetaType<serialport::Pmc960DownloadResult>();
        qRegisterMetaType<editor::ProgramEditor*>();
        resources::initialize(); // the sample program, hello.mpl
    }

    void connectingShowsTheMplMenu() {
        MainWindow window;
        window.show();
        QVERIFY(!menuVisible(window, QStringLiteral("&MPL")));
        QVERIFY(menuVisible(window, QStringLiteral("&Program")));
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        QVERIFY(menuVisible(window, QStringLiteral("&MPL")));
        QVERIFY(!menuVisible(window, QStringLiteral("&Program")));
        QTRY_VERIFY_WITH_TIMEOUT(ws.statusText().contains(QStringLiteral("Ready")), kTimeoutMs);
        QVERIFY(ws.statusDock()->isVisible());
        // MPL's own toolbar, in place of the BDS5's.
        const QStringList mplButtons{QStringLiteral("Download Program"), QStringLiteral("Run Routine"),
                                     QStringLiteral("Stop")};
        QCOMPARE(family_window::toolBarButtons(window), mplButtons);
        QVERIFY(ws.action(QStringLiteral("Run Routine"))->isEnabled());
        window.connectDrive(app::ConnectionChoice::simulator(DriveFamily::Bds5));
        QVERIFY(!ws.isConnected());
        QVERIFY(!menuVisible(window, QStringLiteral("&MPL")));
        QVERIFY(!ws.statusDock()->isVisible());
        QVERIFY(family_window::toolBarButtons(window).contains(QStringLiteral("Run Label")));
        QVERIFY(!family_window::toolBarButtons(window).contains(QStringLiteral("Run Routine")));
    }

    void downloadIsVerifiedAndUploadsTheSame() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        const QString program = example("14-loop-reset-program-G-W.mpl");
        QVERIFY(!program.isEmpty());
        newMplTab(window, QStringLiteral("loop.mpl"), program);
        QVERIFY(editor::MplLanguage::of(window.editor())); // .mpl: the MPL lexer
        QSignalSpy downloaded(&ws.transfer(), &app::Pmc960ProgramTransfer::downloadFinished);
        ws.action(QStringLiteral("Download Program"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(downloaded.count(), 1, kTimeoutMs);
        const auto result = downloaded.at(0).at(0).value<serialport::Pmc960DownloadResult>();
        QVERIFY2(result.ok, qPrintable(result.reason));
        QCOMPARE(result.hostChecksum, result.driveChecksum);
        QVERIFY(ws.transfer().lastMessage().contains(QStringLiteral("verified")));

        QSignalSpy uploaded(&ws.transfer(), &app::Pmc960ProgramTransfer::uploadFinished);
        ws.action(QStringLiteral("Upload Program"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(uploaded.count(), 1, kTimeoutMs);
        QVERIFY(uploaded.at(0).at(0).toBool());
        auto* tab = uploaded.at(0).at(1).value<editor::ProgramEditor*>();
        QVERIFY(tab);
        QCOMPARE(tab->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts),
                 serialport::Pmc960Download::programLines(program));
        QVERIFY(editor::MplLanguage::of(tab));
    }

    void aProgramTooBigGetsTheControllersErrorAndLine() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        QString big = QStringLiteral("@A\n\n");
        for (int i = 0; i < 200; ++i) big += QStringLiteral("@.0123456789\n");
        newMplTab(window, QStringLiteral("big.mpl"), big);
        QSignalSpy downloaded(&ws.transfer(), &app::Pmc960ProgramTransfer::downloadFinished);
        ws.transfer().download(window.editor());
        QTRY_COMPARE_WITH_TIMEOUT(downloaded.count(), 1, 60000);
        const auto result = downloaded.at(0).at(0).value<serialport::Pmc960DownloadResult>();
        QVERIFY(!result.ok);
        QCOMPARE(result.error, 0xC1);
        const int line = downloaded.at(0).at(1).toInt();
        QVERIFY(line > 100);
        QVERIFY(ws.transfer().lastMessage().contains(QStringLiteral("#C1")));
        QVERIFY(ws.transfer().lastMessage().contains(QStringLiteral("line %1").arg(line)));
        int cursorLine = 0, index = 0;
        window.editor()->getCursorPosition(&cursorLine, &index);
        QCOMPARE(cursorLine + 1, line);
    }

    // MPL > Stop while a download runs (issue 11): ESC goes out at once, the download ends cancelled (the
    // progress dialog's own cancel() would only have hidden it), the editor keeps its text.
    void stopDuringADownloadCancelsIt() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected() && ws.statusText().contains(QStringLiteral("Ready")), kTimeoutMs);
        QString program = QStringLiteral("@A\n");
        for (int i = 1; i <= 60; ++i) program += QStringLiteral("A%1\n").arg(i * 10);
        newMplTab(window, QStringLiteral("long.mpl"), program);
        QSignalSpy downloaded(&ws.transfer(), &app::Pmc960ProgramTransfer::downloadFinished);
        QSignalSpy messages(&ws, &app::FamilyWorkspace::message);
        ws.action(QStringLiteral("Download Program"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(ws.transfer().progressDialog() && ws.transfer().progressDialog()->progressValue() >= 3,
                                 kTimeoutMs);
        ws.action(QStringLiteral("Stop"))->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(downloaded.count(), 1, kTimeoutMs);
        const auto result = downloaded.at(0).at(0).value<serialport::Pmc960DownloadResult>();
        QVERIFY(!result.ok);
        QVERIFY2(result.cancelled, qPrintable(result.reason));
        QVERIFY2(ws.transfer().lastMessage().startsWith(QStringLiteral("Download cancelled after")),
                 qPrintable(ws.transfer().lastMessage()));
        bool saidEsc = false;
        for (const auto& m : messages) saidEsc |= m.at(0).toString().startsWith(QStringLiteral("Stop: ESC sent"));
        QVERIFY(saidEsc);
        QCOMPARE(window.editor()->text(), program);
        QTRY_VERIFY_WITH_TIMEOUT(ws.statusText().contains(QStringLiteral("Ready")), kTimeoutMs);
        QVERIFY(ws.action(QStringLiteral("Download Program"))->isEnabled());
    }

    // MPL > Run Routine (the MPL menu had no Run): the labels of hello.mpl as the dialog lists them, comment
    // lines (@.) left out; H picked with Enter and "Enable the servo first" ticked types SM2 then BH, and the
    // Terminal shows what BH shows (12288: three turns).
    void runRoutineListsTheLabelsAndRunsHelloWithTheServoEnabledFirst() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected() && ws.statusText().contains(QStringLiteral("Ready")), kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(ws.statusDock()->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM0")),
                                 kTimeoutMs);
        QFile sample(ws.sampleProgram());
        QVERIFY(sample.open(QIODevice::ReadOnly));
        newMplTab(window, QStringLiteral("hello.mpl"), QString::fromUtf8(sample.readAll()));
        QVERIFY(downloadCurrentTab(ws));
        QCOMPARE(ws.action(QStringLiteral("Run Routine"))->shortcut(), QKeySequence(QStringLiteral("Ctrl+F5")));

        app::Pmc960RunDialog* dialog = openRunRoutine(window, ws);
        QVERIFY(dialog);
        QCOMPARE(dialog->windowTitle(), QStringLiteral("Run Routine"));
        QCOMPARE(itemTexts(dialog->list()),
                 QStringList({QStringLiteral("H  Hello: set up, then three turns forward"),
                              QStringLiteral("T  Turn: index one turn, wait for the end; LT2 repeats it twice more"),
                              QStringLiteral("P  Position: let the motor settle 250 ms, show its position, quit"),
                              QStringLiteral("R  Return: set up, three turns back, then show the position"),
                              QStringLiteral("S  Set up: drive on in position mode, acceleration, speed, one turn")}));
        QVERIFY2(dialog->servoNote().contains(QStringLiteral("not enabled (SM0)")), qPrintable(dialog->servoNote()));
        QVERIFY(dialog->enableServoFirst()->isVisible());
        QVERIFY(!dialog->enableServoFirst()->isChecked()); // enabling the servo is the user's choice

        QSignalSpy finished(&ws.runner(), &app::Pmc960RoutineRunner::finished);
        dialog->list()->setCurrentRow(0);
        QTest::keyClick(dialog->enableServoFirst(), Qt::Key_Space);
        QVERIFY(dialog->enableServoFirst()->isChecked());
        QPointer<app::Pmc960RunDialog> open(dialog);
        QTest::keyClick(dialog->list(), Qt::Key_Return); // Enter in the list: Run
        QTRY_VERIFY_WITH_TIMEOUT(!open || !open->isVisible(), kTimeoutMs);

        app::TerminalWidget* terminal = window.terminal();
        QTRY_VERIFY2_WITH_TIMEOUT(terminal->text().contains(QStringLiteral("BH12288")), qPrintable(terminal->text()),
                                  kRunTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kRunTimeoutMs);
        QCOMPARE(finished.at(0).at(0).value<QChar>(), QLatin1Char('H'));
        QCOMPARE(finished.at(0).at(1).toInt(), 0);
        const QString text = terminal->text();
        QVERIFY2(text.lastIndexOf(QStringLiteral("SM2")) >= 0 &&
                     text.lastIndexOf(QStringLiteral("SM2")) < text.lastIndexOf(QStringLiteral("BH12288")),
                 qPrintable(text)); // SM2 went first
        QVERIFY2(ws.runner().lastMessage().contains(QStringLiteral("Routine H ended")),
                 qPrintable(ws.runner().lastMessage()));
        QTRY_VERIFY_WITH_TIMEOUT(ws.statusDock()->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM2")),
                                 kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(ws.statusDock()->value(QStringLiteral("position")), QStringLiteral("12288"),
                                  kTimeoutMs);
    }

    // A routine the controller refuses: the editor's program has a label the drive's does not (the drive holds
    // the program downloaded before), so B<label> gets #C2, and the status bar, the Terminal and the error log
    // say so, with the hint that the program in the drive may differ from the editor and how to download it.
    // A program without labels offers nothing to run.
    void aRefusedRoutineSaysTheProgramInTheDriveMayDiffer() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected() && ws.statusText().contains(QStringLiteral("Ready")), kTimeoutMs);

        newMplTab(window, QStringLiteral("nolabels.mpl"), QStringLiteral("@.only_a_comment\nA100\n"));
        app::Pmc960RunDialog* empty = openRunRoutine(window, ws);
        QVERIFY(empty);
        QCOMPARE(empty->list()->count(), 0);
        QVERIFY(!empty->runButton()->isEnabled());
        bool saysNone = false;
        for (const QLabel* label : empty->findChildren<QLabel*>())
            saysNone |= label->isVisible() && label->text().contains(QStringLiteral("has no labels"));
        QVERIFY(saysNone);
        empty->reject();
        QTRY_VERIFY_WITH_TIMEOUT(!window.findChild<app::Pmc960RunDialog*>(), kTimeoutMs);

        newMplTab(window, QStringLiteral("turn.mpl"), QStringLiteral("@H_Half_a_turn\nI2048+,\nG!\nE\n"));
        QVERIFY(downloadCurrentTab(ws));
        newMplTab(window, QStringLiteral("kick.mpl"), QStringLiteral("@K_Kick\nI100+\nE\n")); // not downloaded
        QTRY_VERIFY_WITH_TIMEOUT(ws.statusDock()->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM0")),
                                 kTimeoutMs);
        app::Pmc960RunDialog* dialog = openRunRoutine(window, ws);
        QVERIFY(dialog);
        QCOMPARE(itemTexts(dialog->list()), QStringList(QStringLiteral("K  Kick")));
        QVERIFY(dialog->servoNote().contains(QStringLiteral("SM0")));
        QVERIFY(!dialog->enableServoFirst()->isChecked());
        QSignalSpy finished(&ws.runner(), &app::Pmc960RoutineRunner::finished);
        QTest::mouseClick(dialog->runButton(), Qt::LeftButton);

        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kRunTimeoutMs);
        QCOMPARE(finished.at(0).at(1).toInt(), 0xC2);
        const QString said = ws.runner().lastMessage();
        QVERIFY2(said.contains(QStringLiteral("refused routine K (BK)")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("#C2")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("may differ from the editor")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("MPL > Download Program, Shift+F5")), qPrintable(said));
        // Where the user looks: the status bar, the Terminal, the error log.
        QTRY_COMPARE_WITH_TIMEOUT(window.statusBar()->currentMessage(), said, kTimeoutMs);
        QTRY_VERIFY2_WITH_TIMEOUT(window.terminal()->text().contains(QStringLiteral("may differ from the editor")),
                                  qPrintable(window.terminal()->text()), kTimeoutMs);
        const app::ErrorLogModel& log = ws.errorSource()->model();
        QTRY_VERIFY_WITH_TIMEOUT(log.rowCount() > 0, kTimeoutMs);
        QCOMPARE(log.entry(0).codeText, QStringLiteral("#C2"));
        QCOMPARE(log.entry(0).detail, QStringLiteral("BK"));
        QVERIFY(!ws.runner().isRunning());
    }

    // Issue 19: a routine that stops on an error inside its program was blamed on the B<label> that started it,
    // with no line. The controller prints only #B6; its SB& (the last label passed, the commands since) followed
    // through the downloaded program names the command that failed and its line — here after a called routine
    // returned, past an empty line the download leaves out — in the status bar, the Terminal and the error log,
    // whose row a double-click shows in the program's editor; and so when BH is typed in the Terminal.
    void aProgramErrorNamesTheFailingCommandAndItsLine() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected() && ws.statusText().contains(QStringLiteral("Ready")), kTimeoutMs);
        editor::ProgramEditor* program =
            newMplTab(window, QStringLiteral("turn.mpl"),
                      QStringLiteral("@H_Half_a_turn\nFS\n\nI2048+,\nG!\nE\n@S_Set_up\nA4000\nE\n"));
        QVERIFY(downloadCurrentTab(ws));
        QTRY_VERIFY_WITH_TIMEOUT(ws.statusDock()->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM0")),
                                 kTimeoutMs);
        QSignalSpy finished(&ws.runner(), &app::Pmc960RoutineRunner::finished);
        ws.runner().run(QLatin1Char('H'), false); // the servo left off: I2048+, is refused

        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kRunTimeoutMs);
        QCOMPARE(finished.at(0).at(0).value<QChar>(), QLatin1Char('H'));
        QCOMPARE(finished.at(0).at(1).toInt(), 0xB6);
        const QString said = ws.runner().lastMessage();
        QVERIFY2(said.startsWith(QStringLiteral("Error: routine H stopped at line 4, I2048+, (SB& S 1")),
                 qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("#B6 Servodrive not enabled")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("Enable the servo first (SM2)")), qPrintable(said));
        QVERIFY2(!said.contains(QStringLiteral("may differ")), qPrintable(said)); // the drive holds this program
        QTRY_COMPARE_WITH_TIMEOUT(window.statusBar()->currentMessage(), said, kTimeoutMs);
        QTRY_VERIFY2_WITH_TIMEOUT(window.terminal()->text().contains(QStringLiteral("stopped at line 4, I2048+,")),
                                  qPrintable(window.terminal()->text()), kTimeoutMs);

        app::ErrorLogDock& dock = *window.errorLogDock();
        const app::ErrorLogModel& log = dock.model();
        QTRY_VERIFY_WITH_TIMEOUT(log.rowCount() > 0, kTimeoutMs);
        QCOMPARE(log.rowCount(), 1); // one row for the error, not another for BH
        QCOMPARE(log.index(0, app::ErrorLogModel::Code).data().toString(), QStringLiteral("#B6"));
        QCOMPARE(log.index(0, app::ErrorLogModel::Message).data().toString(),
                 QStringLiteral("Servodrive not enabled 'I2048+, in routine H'"));
        QCOMPARE(log.index(0, app::ErrorLogModel::Line).data().toString(), QStringLiteral("4"));

        // Another tab is current and the cursor elsewhere: activating the row shows line 4 of the program.
        newMplTab(window, QStringLiteral("other.mpl"), QString());
        QVERIFY(window.editor() != program);
        program->setCursorPosition(0, 0);
        emit dock.view()->activated(log.index(0, app::ErrorLogModel::Line));
        QCOMPARE(window.editor(), program);
        int line = -1, index = -1;
        program->getCursorPosition(&line, &index);
        QCOMPARE(line + 1, 4);

        // BH typed in the Terminal, as hello.mpl says to run a routine: placed the same, not blamed on BH.
        app::TerminalWidget* terminal = window.terminal();
        terminal->setFocus();
        QTest::keyClicks(terminal, QStringLiteral("BH"));
        QTest::keyClick(terminal, Qt::Key_Return);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, kRunTimeoutMs);
        QCOMPARE(finished.at(1).at(1).toInt(), 0xB6);
        QTRY_COMPARE_WITH_TIMEOUT(log.rowCount(), 2, kTimeoutMs);
        QCOMPARE(log.index(0, app::ErrorLogModel::Message).data().toString(),
                 QStringLiteral("Servodrive not enabled 'I2048+, in routine H'"));
        QCOMPARE(log.index(0, app::ErrorLogModel::Line).data().toString(), QStringLiteral("4"));
        QVERIFY2(ws.runner().lastMessage().startsWith(QStringLiteral("Error: routine H stopped at line 4, I2048+,")),
                 qPrintable(ws.runner().lastMessage()));
    }

    // Issue 19: the status panel froze while a routine ran — position and velocity stayed put until the prompt
    // came back. Its polls go on during the routine: while MPL > Run Routine's B<label> still runs, the position
    // climbs and the velocity shows.
    void statusPanelFollowsARunningRoutine() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected() && ws.statusText().contains(QStringLiteral("Ready")), kTimeoutMs);
        app::Pmc960StatusDock* status = ws.statusDock();
        QTRY_COMPARE_WITH_TIMEOUT(status->value(QStringLiteral("position")), QStringLiteral("0"), kTimeoutMs);
        newMplTab(window, QStringLiteral("move.mpl"),
                  QStringLiteral("@M_Ten_turns_slowly\nSM2\nA4000\nV40\nI40960+,\nG!\nE\n")); // about 10 s
        // Ten seconds of the simulator's real time: under load (ctest -j 4 beside CPU hogs) the GUI thread may
        // poll the status only every few seconds, and a 4 s routine once ended between two of its updates.
        QVERIFY(downloadCurrentTab(ws));
        QSignalSpy finished(&ws.runner(), &app::Pmc960RoutineRunner::finished);
        ws.runner().run(QLatin1Char('M'), false);
        QVERIFY(ws.runner().isRunning());
        auto position = [status] { return status->value(QStringLiteral("position")).toInt(); };
        QTRY_VERIFY_WITH_TIMEOUT(ws.runner().isRunning() && position() > 0, kRunTimeoutMs);
        const int first = position();
        QTRY_VERIFY_WITH_TIMEOUT(ws.runner().isRunning() && position() > first, kRunTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(ws.runner().isRunning() && status->value(QStringLiteral("velocity")).toInt() > 0,
                                 kRunTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kRunTimeoutMs);
        QCOMPARE(finished.at(0).at(1).toInt(), 0);
        QVERIFY2(ws.runner().lastMessage().contains(QStringLiteral("Routine M ended")),
                 qPrintable(ws.runner().lastMessage()));
        QTRY_VERIFY_WITH_TIMEOUT(position() > 40000, kTimeoutMs);
    }

    void statusPanelFollowsAMove() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        app::Pmc960StatusDock* status = ws.statusDock();
        QTRY_COMPARE_WITH_TIMEOUT(status->value(QStringLiteral("position")), QStringLiteral("0"), kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(status->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM0")), kTimeoutMs);
        status->sendCommand(QStringLiteral("SM2"));
        status->sendCommand(QStringLiteral("OB5:F"));
        status->sendCommand(QStringLiteral("I4000+"));
        QTRY_VERIFY_WITH_TIMEOUT(status->value(QStringLiteral("position")).toInt() > 0, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(status->value(QStringLiteral("position")), QStringLiteral("4000"), kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(status->value(QStringLiteral("mode")).startsWith(QStringLiteral("SM2")), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(status->value(QStringLiteral("outputs")), QStringLiteral("0005"), kTimeoutMs);
    }

    void parameterTableShowsStoredAndInUseAndWrites() {
        MainWindow window;
        window.show();
        Pmc960Workspace& ws = connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        app::VariableBrowser* table = ws.parameterBrowser();
        const app::VariableModel& model = table->model();
        QCOMPARE(model.variableCount(), int(drive_core::catalog::pmc960::parameters().size()));
        // Every parameter is read once on connecting: stored (?) and in use (!).
        QTRY_VERIFY_WITH_TIMEOUT(!model.second(QStringLiteral("TGP")).isEmpty() && table->sync().pending() == 0,
                                 kTimeoutMs);
        QCOMPARE(model.value(QStringLiteral("TGP")), QStringLiteral("16"));
        QCOMPARE(model.second(QStringLiteral("TGP")), QStringLiteral("16"));
        QCOMPARE(model.value(QStringLiteral("A")), QStringLiteral("4000")); // stored vs in use while still
        QCOMPARE(model.second(QStringLiteral("A")), QStringLiteral("0"));
        QVERIFY(model.indexOf(QStringLiteral("A"), app::VariableModel::Second).data(Qt::BackgroundRole).isValid());
        QCOMPARE(model.value(QStringLiteral("THI")), QStringLiteral("="));
        QVERIFY(!table->sync().isLive()); // read when asked: each read is a command on the user's queue

        QVERIFY(!table->editValue(QStringLiteral("TGP"), QStringLiteral("300"))); // the catalog's limit
        QVERIFY2(table->statusText().contains(QStringLiteral("0 \u2013 255")), qPrintable(table->statusText()));

        QSignalSpy written(table, &app::VariableBrowser::written);
        QVERIFY(table->editValue(QStringLiteral("TGP"), QStringLiteral("20")));
        QTRY_COMPARE_WITH_TIMEOUT(written.count(), 1, kTimeoutMs);
        QVERIFY(written.at(0).at(1).toBool());
        QTRY_COMPARE_WITH_TIMEOUT(model.value(QStringLiteral("TGP")), QStringLiteral("20"), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(model.second(QStringLiteral("TGP")), QStringLiteral("20"), kTimeoutMs);

        // Copy as MPL lines: a T-table value as the line that sets it, between SW1 and SW0 (the parameter file
        // vars send takes); a system register (SM) is no part of a parameter backup.
        table->model().setPinned(QStringLiteral("TGP"), true);
        table->model().setPinned(QStringLiteral("SM"), true);
        table->showWatchList(true);
        QCOMPARE(table->copyButton()->text(), QStringLiteral("Copy as MPL lines"));
        const auto lines = table->selectionAsFile();
        QCOMPARE(lines.count, 1);
        QCOMPARE(lines.text, QStringLiteral("SW1\nTGP20\nSW0\n"));
        table->showWatchList(false);

        // The controller's own refusal: TGF 200 overflows the 384 kHz range (#9C).
        QVERIFY(table->editValue(QStringLiteral("TGF"), QStringLiteral("200")));
        QTRY_COMPARE_WITH_TIMEOUT(written.count(), 2, kTimeoutMs);
        QVERIFY(!written.at(1).at(1).toBool());
        QVERIFY2(table->statusText().contains(QStringLiteral("#9C")), qPrintable(table->statusText()));
        QTRY_COMPARE_WITH_TIMEOUT(model.value(QStringLiteral("TGF")), QStringLiteral("16"), kTimeoutMs);

        // It is the family's variable browser: titled so, and searchable by name or description.
        QVERIFY(ws.parameterDock()->windowTitle().startsWith(QStringLiteral("Variables")));
        const QAbstractItemModel& shown = *table->allView()->model();
        const auto shownNames = [&shown] {
            QStringList names;
            for (int g = 0; g < shown.rowCount(); ++g)
                for (int r = 0; r < shown.rowCount(shown.index(g, 0)); ++r)
                    names << shown.index(r, 0, shown.index(g, 0)).data(app::VariableModel::NameRole).toString();
            return names;
        };
        table->setFilter(QStringLiteral("gain"));
        QVERIFY(shownNames().contains(QStringLiteral("TGP"))); // "position loop gain"
        QVERIFY(!shownNames().contains(QStringLiteral("SF")));
        table->setFilter(QString());
        QCOMPARE(shownNames().size(), model.variableCount());
    }

    void mplFilesGetMplHighlightingAndHelp() {
        MainWindow window;
        window.show();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("t.mpl"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("@T\nI+,\nLT9\nE\n");
        file.close();
        QVERIFY(window.editorArea()->documents()->openFile(path));
        auto* language = editor::MplLanguage::of(window.editor());
        QVERIFY(language);
        QVERIFY(qobject_cast<editor::MplLexer*>(window.editor()->lexer()));
        window.editor()->setCursorPosition(2, 0);
        QCOMPARE(language->showHelpAtCursor(), QStringLiteral("L"));
        QVERIFY(language->helpPopup()->html().contains(QStringLiteral("LOOP"), Qt::CaseInsensitive));
    }
};

QTEST_MAIN(Pmc960WorkspaceTest)
#include "pmc960_workspace_test.moc"
