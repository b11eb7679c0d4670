// The Program and Variables menus against the simulated BDS5 at 9600 baud, asserting what a user sees: the
// terminal, the status bar, the progress dialog, new tabs, and marks at the right editor lines.
#include "app_test_support.h"
#include "app/families/bds5/bds5_workspace.h"
#include "families/bds5/drive_connection.h"
#include "app/editing/editor_area.h"
#include "app/editing/editor_tabs.h"
#include "app/main_window.h"
#include "families/bds5/program_controller.h"
#include "app/drive/terminal_widget.h"
#include "app/transfer/transfer_dialog.h"
#include "app/transfer/transfer_markers.h"
#include "families/bds5/variables_controller.h"

#include "editor/program_editor.h"

#include <QInputDialog>
#include <QMessageBox>
#include <QPushButton>
#include <QProgressBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

using app::MainWindow;
using app::TransferMarkers;
using Result = serialport::Bds5TransferResult;
using Status = Result::Status;

namespace {
using app_test::kDriveTimeoutMs;
using app_test::driveReady;
const QString kHelloWorld = QStringLiteral("10$\nP \"HELLO WORLD\"\nB\n"); // the manual's first session

struct Window {
    MainWindow window;
    Window() {
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
    }
    bool ready() {
        return QTest::qWaitFor([this] { return driveReady(window); }, kDriveTimeoutMs);
    }
    void type(const QString& text) { // as a user types into the terminal
        QTest::keyClicks(window.terminal(), text);
        QTest::keyClick(window.terminal(), Qt::Key_Return);
    }
    template <typename Controller, typename Action> Result run(Controller& controller, Action action) {
        QSignalSpy finished(&controller, &Controller::transferFinished);
        (controller.*action)();
        if (!finished.wait(kDriveTimeoutMs)) return {Status::Failed, QStringLiteral("test: no result")};
        return finished.first().at(0).template value<Result>();
    }
    Result download() { return run(window.programController(), &app::ProgramController::download); }
    // F5 on a program the editor finds errors in, answered "Download Anyway" as a user who wants the drive's
    // own answer would.
    Result downloadAnyway() {
        QSignalSpy finished(&window.programController(), &app::ProgramController::transferFinished);
        window.programController().download();
        QMessageBox* question = window.programController().downloadQuestion();
        if (!question) return {Status::Failed, QStringLiteral("test: no question about the errors")};
        for (QAbstractButton* b : question->buttons())
            if (b->text().contains(QStringLiteral("Anyway"))) b->click();
        if (!finished.wait(kDriveTimeoutMs)) return {Status::Failed, QStringLiteral("test: no result")};
        return finished.first().at(0).value<Result>();
    }
};
} // namespace

static QByteArray allSent(const QSignalSpy& spy) {
    QByteArray bytes;
    for (const QList<QVariant>& s : spy) bytes += s.at(0).toByteArray();
    return bytes;
}

class ProgramTransferTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskTest"));
    }

    void helloWorldDownloadedThenRunShowsInTheTerminal() {
        Window w;
        QVERIFY(w.ready());
        w.window.editor()->setText(kHelloWorld);
        w.window.programController().setStripComments(false);
        const Result r = w.download();
        QVERIFY2(r.ok(), qPrintable(r.summary));
        QVERIFY2(w.window.statusBar()->currentMessage().contains(QStringLiteral("Verified")),
                 qPrintable(w.window.statusBar()->currentMessage()));
        QVERIFY(w.window.terminal()->text().contains(QStringLiteral("P CHECKSUM = %1").arg(*r.checksum)));
        QVERIFY(!app::TransferDialog::active()); // the progress dialog went away on success
        QVERIFY(w.ready());
        w.type(QStringLiteral("RUN 10"));
        QTRY_VERIFY_WITH_TIMEOUT(
            w.window.terminal()->text().split(QLatin1Char('\n')).contains(QStringLiteral("HELLO WORLD")),
            kDriveTimeoutMs);
    }

    void programFromDriveOpensTheSameTextInANewTab() {
        Window w;
        QVERIFY(w.ready());
        const QString text = QStringLiteral("; hello\n10$\nP \"HELLO WORLD\" ; greet\nB\n");
        w.window.editor()->setText(text);
        QVERIFY(w.download().ok());
        const int tabsBefore = w.window.editorArea()->tabs()->count();
        const Result r = w.run(w.window.programController(), &app::ProgramController::fromDrive);
        QVERIFY2(r.ok(), qPrintable(r.summary));
        QCOMPARE(w.window.editorArea()->tabs()->count(), tabsBefore + 1);
        QCOMPARE(w.window.editor()->text(), text);
        QVERIFY(w.window.windowTitle().startsWith(QStringLiteral("drive-program.bds")));
    }

    void runtimeErrorIsMarkedAtTheEditorLineWhenCommentsWereStripped() {
        Window w;
        QVERIFY(w.ready());
        w.window.editor()->setText(QStringLiteral("; move table\n"
                                                  "10$\n"
                                                  "; a dwell that cannot be\n"
                                                  "\n"
                                                  "P \"START\" ; say so\n"
                                                  "D -1\n"
                                                  "B\n"));
        w.window.programController().setStripComments(true);
        const Result r = w.downloadAnyway(); // the editor already underlines D -1
        w.window.programController().setStripComments(false);
        QVERIFY2(r.ok(), qPrintable(r.summary));
        QVERIFY(w.ready());
        w.type(QStringLiteral("RUN 10"));
        // The drive reports its own line 3; the editor shows it on line 6.
        QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().contains(QStringLiteral("ERR 83 LINE 3")),
                                 kDriveTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(TransferMarkers::markedLines(*w.window.editor()), QList<int>{6},
                                  kDriveTimeoutMs);
        QVERIFY2(
            TransferMarkers::annotationAt(*w.window.editor(), 6).contains(QStringLiteral("ERR 83 LINE 3")),
            qPrintable(TransferMarkers::annotationAt(*w.window.editor(), 6)));
        QVERIFY(w.window.statusBar()->currentMessage().startsWith(
            QStringLiteral("Editor line 6: ERR 83 LINE 3")));
    }

    void verifyMarksTheLineChangedOnTheDrive() {
        Window w;
        QVERIFY(w.ready());
        w.window.editor()->setText(kHelloWorld);
        QVERIFY(w.download().ok());
        QVERIFY(w.ready());
        // Behind the IDE's back: the program is reloaded from the terminal with line 2 changed.
        w.type(QStringLiteral(">BDS"));
        for (const QString& line :
             {QStringLiteral("10$"), QStringLiteral("P \"HELLO MARS\""), QStringLiteral("B")}) {
            QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().endsWith(QStringLiteral("l->")),
                                     kDriveTimeoutMs);
            w.type(line);
        }
        QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().endsWith(QStringLiteral("l->")),
                                 kDriveTimeoutMs);
        QTest::keyClick(w.window.terminal(), Qt::Key_Escape);
        QVERIFY(w.ready());
        const Result r = w.run(w.window.programController(), &app::ProgramController::verify);
        QCOMPARE(r.status, Status::Mismatch);
        QCOMPARE(TransferMarkers::markedLines(*w.window.editor()), QList<int>{2});
        QCOMPARE(TransferMarkers::annotationAt(*w.window.editor(), 2),
                 QStringLiteral("Verify: the drive holds \"P \"HELLO MARS\"\" here"));
        QVERIFY(app::TransferDialog::active() == nullptr);
        auto* dialog = w.window.findChild<app::TransferDialog*>();
        QVERIFY(dialog && dialog->isVisible()); // the failure stays on screen until closed
        QVERIFY(dialog->resultText().contains(QStringLiteral("drive line 2")));
    }

    // Issue 19, item 5: F5 on a program the editor finds errors in asks first (Download Anyway / Cancel);
    // Cancel sends nothing and says why, Download Anyway downloads and the drive's refusal is reported.
    void downloadOfAProgramWithErrorsAsksFirst() {
        Window w;
        QVERIFY(w.ready());
        w.window.editor()->setText(QStringLiteral("10$\nX1=1\nFROB 2\nB\n"));
        QSignalSpy sent(&w.window.connection(), &app::DriveConnection::rawSent);
        QSignalSpy finished(&w.window.programController(), &app::ProgramController::transferFinished);
        w.window.programController().download();
        QMessageBox* question = w.window.programController().downloadQuestion();
        QVERIFY(question && question->isVisible());
        QVERIFY2(question->text().contains(QStringLiteral("line 3")), qPrintable(question->text()));
        QVERIFY(!app::TransferDialog::active());
        question->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY_WITH_TIMEOUT(!w.window.programController().downloadQuestion(), kDriveTimeoutMs);
        QVERIFY2(w.window.statusBar()->currentMessage().contains(QStringLiteral("cancelled")),
                 qPrintable(w.window.statusBar()->currentMessage()));
        int line = -1, index = -1;
        w.window.editor()->getCursorPosition(&line, &index);
        QCOMPARE(line, 2); // the cursor on the first error's line
        QVERIFY(sent.isEmpty() && finished.isEmpty());

        w.window.programController().download();
        question = w.window.programController().downloadQuestion();
        QVERIFY(question);
        QPushButton* anyway = nullptr;
        for (QAbstractButton* b : question->buttons())
            if (b->text().contains(QStringLiteral("Anyway"))) anyway = qobject_cast<QPushButton*>(b);
        QVERIFY(anyway);
        anyway->click();
        QVERIFY(finished.wait(kDriveTimeoutMs));
        // The drive stores program lines as they come (program-load mode) and says ERR 80 when it runs them.
        const auto result = finished.first().at(0).value<Result>();
        QVERIFY2(result.ok(), qPrintable(result.summary));
        QVERIFY(allSent(sent).contains("FROB 2\r"));
    }

    void cancelMidDownloadSaysTheDriveHoldsPartOfTheProgram() {
        Window w;
        QVERIFY(w.ready());
        QString text;
        for (int i = 1; i <= 60; ++i)
            text += QStringLiteral("X%1=%1\n").arg(i);
        w.window.editor()->setText(text);
        QSignalSpy finished(&w.window.programController(), &app::ProgramController::transferFinished);
        w.window.programController().download();
        app::TransferDialog* dialog = app::TransferDialog::active();
        QVERIFY(dialog && dialog->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(dialog->findChild<QProgressBar*>()->value() >= 5, kDriveTimeoutMs);
        dialog->reject(); // the Cancel button
        QVERIFY(finished.wait(kDriveTimeoutMs));
        const auto r = finished.first().at(0).value<Result>();
        QCOMPARE(r.status, Status::Cancelled);
        QVERIFY(r.linesDone >= 5 && r.linesDone < 60);
        QVERIFY(dialog->isVisible());
        QVERIFY2(dialog->resultText().contains(QStringLiteral("only the first %1 line(s)").arg(r.linesDone)),
                 qPrintable(dialog->resultText()));
        QVERIFY(w.ready()); // back at the --> prompt
    }

    void wrongPasswordIsRefusedThenAskedForAndTheDownloadRetried() {
        Window w;
        QVERIFY(w.ready());
        w.window.editor()->setText(kHelloWorld);
        QVERIFY(w.download().ok());
        QVERIFY(w.ready());
        w.type(QStringLiteral("ED"));
        QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().endsWith(QStringLiteral("e->")),
                                 kDriveTimeoutMs);
        w.type(QStringLiteral("PASS"));
        QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().endsWith(QStringLiteral("e->")),
                                 kDriveTimeoutMs);
        w.type(QStringLiteral("KEY1"));
        QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().endsWith(QStringLiteral("e->")),
                                 kDriveTimeoutMs);
        QTest::keyClick(w.window.terminal(), Qt::Key_Escape);
        QVERIFY(w.ready());

        QSignalSpy finished(&w.window.programController(), &app::ProgramController::transferFinished);
        w.window.programController().download();
        QVERIFY(finished.wait(kDriveTimeoutMs));
        const auto refused = finished.takeFirst().at(0).value<Result>();
        QCOMPARE(refused.status, Status::Refused);
        QVERIFY(w.window.statusBar()->currentMessage().contains(QStringLiteral("ERR 110")));
        auto* ask = w.window.findChild<QInputDialog*>(QStringLiteral("drivePasswordDialog"));
        QVERIFY(ask && ask->isVisible());
        ask->setTextValue(QStringLiteral("key1"));
        ask->accept();
        QVERIFY(finished.wait(kDriveTimeoutMs));
        const auto accepted = finished.takeFirst().at(0).value<Result>();
        QVERIFY2(accepted.ok(), qPrintable(accepted.summary));
    }

    void variablesFromDriveThenSendBackRestoresTheValues() {
        Window w;
        QVERIFY(w.ready());
        w.type(QStringLiteral("X7=4321"));
        QVERIFY(w.ready());
        auto& vars = w.window.bds5().variablesController();
        const Result read = w.run(vars, &app::VariablesController::fromDrive);
        QVERIFY2(read.ok(), qPrintable(read.summary));
        QVERIFY(w.window.windowTitle().startsWith(QStringLiteral("drive-variables.var")));
        QVERIFY(w.window.editor()->text().contains(QStringLiteral("\nX7 4321\n")));
        QVERIFY(w.ready());
        w.type(QStringLiteral("X7=0"));
        QVERIFY(w.ready());
        const Result sent = w.run(vars, &app::VariablesController::sendToDrive);
        QVERIFY2(sent.ok() && sent.errors.isEmpty(), qPrintable(sent.summary));
        QVERIFY(w.ready());
        w.type(QStringLiteral("P X7"));
        QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().contains(QStringLiteral("\n        4321\n")),
                                 kDriveTimeoutMs);
    }

    void sendingAVariableFileMarksEachRefusedLine() {
        Window w;
        QVERIFY(w.ready());
        w.window.bds5().variablesController().newVariables();
        w.window.editor()->setText(QStringLiteral("; my set\nX1 5\nKP 99999999\nVMAX 100\nX2 6\n"));
        const Result r = w.run(w.window.bds5().variablesController(), &app::VariablesController::sendToDrive);
        QCOMPARE(r.linesDone, 4);
        QCOMPARE(TransferMarkers::markedLines(*w.window.editor()), (QList<int>{3, 4}));
        QVERIFY(TransferMarkers::annotationAt(*w.window.editor(), 4).startsWith(QStringLiteral("ERR 111")));
    }

    void dumpWithTheDriveEnabledExplainsErr51() {
        Window w;
        QVERIFY(w.ready());
        w.type(QStringLiteral("EN"));
        QVERIFY(w.ready());
        const Result r = w.run(w.window.bds5().variablesController(), &app::VariablesController::fromDrive);
        QCOMPARE(r.status, Status::Refused);
        const QString shown = w.window.statusBar()->currentMessage();
        QVERIFY2(shown.contains(QStringLiteral("ERR 51")) && shown.contains(QStringLiteral("disabled")),
                 qPrintable(shown));
        auto* dialog = w.window.findChild<app::TransferDialog*>();
        QVERIFY(dialog && dialog->resultText() == r.summary);
    }

    void resetToStandardVarPutsFactoryValuesBack() {
        Window w;
        QVERIFY(w.ready());
        w.type(QStringLiteral("KP=123"));
        QVERIFY(w.ready());
        const Result r = w.run(w.window.bds5().variablesController(), &app::VariablesController::sendStandard);
        QVERIFY2(r.ok() && r.errors.isEmpty(), qPrintable(r.summary));
        QVERIFY(r.linesDone > 50);
        QVERIFY(w.ready());
        w.type(QStringLiteral("P KP"));
        QTRY_VERIFY_WITH_TIMEOUT(w.window.terminal()->text().contains(QStringLiteral("\n        1500\n")),
                                 kDriveTimeoutMs);
    }
};

QTEST_MAIN(ProgramTransferTest)
#include "program_transfer_test.moc"
