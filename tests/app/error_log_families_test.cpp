// The error log for the SC750 and the PMC-960 (issues 8, 9), in the real MainWindow against the simulated
// controllers, driven as a user would: a ServoBASIC program that divides by zero stops with F 4 and its row
// names the code, the drive's message and the line, which a double-click shows in the .bas editor; a
// compile error is a row too; Read Fault reads FAULTCODE; a PMC-960 command typed in the Terminal that the
// controller refuses with #xx is a row decoded from the catalog; ESTOP' asserted during a move gives the
// asynchronous #E0, and Read Last Error reads it back from the `&` error-status buffer. The one dock
// follows the chosen family.
#include "family_window.h"
#include "app/drive/terminal_widget.h"
#include "app/errors/error_log_dock.h"
#include "app/errors/error_log_model.h"
#include "app/errors/error_source.h"
#include "app/main_window.h"
#include "families/pmc960/pmc960_status_dock.h"
#include "families/pmc960/pmc960_workspace.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_workspace.h"

#include "drive_core/simulator_controls.h"
#include "editor/program_editor.h"
#include "editor_area.h"
#include "editor_tabs.h"
#include "serialport/simulator_link.h"

#include <QAction>
#include <QFile>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using app::ErrorLogModel;
using app::MainWindow;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 20000;

QString cell(const ErrorLogModel& model, int row, int column) {
    return model.index(row, column).data().toString();
}

// The first row whose Code column reads code, or -1.
int rowOf(const ErrorLogModel& model, const QString& code,
          ErrorLogModel::Origin origin = ErrorLogModel::Origin::Reported) {
    for (int row = 0; row < model.rowCount(); ++row)
        if (cell(model, row, ErrorLogModel::Code) == code && model.entry(row).origin == origin) return row;
    return -1;
}

QString rows(const ErrorLogModel& model) {
    QStringList out;
    for (int row = 0; row < model.rowCount(); ++row) {
        QStringList cells;
        for (int c = 0; c < ErrorLogModel::ColumnCount; ++c) cells << cell(model, row, c);
        out << cells.join(QLatin1Char('|'));
    }
    return out.join(QLatin1Char('\n'));
}

void type(app::TerminalWidget* terminal, const QString& text) {
    for (const QChar c : text) {
        if (c == QLatin1Char('\r'))
            QTest::keyClick(terminal, Qt::Key_Return);
        else
            QTest::keyClicks(terminal, QString(c));
    }
}

int cursorLine(editor::ProgramEditor* editor) {
    int line = -1, index = -1;
    editor->getCursorPosition(&line, &index);
    return line;
}
} // namespace

class ErrorLogFamiliesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskErrorLogFamiliesTest"));
        QSettings().clear();
    }

    void sc750RunTimeErrorIsARowThatGoesToItsLine() {
        MainWindow window;
        window.show();
        auto& ws = family_window::connectSc750(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        app::ErrorLogDock& dock = *window.errorLogDock();
        dock.show();
        QCOMPARE(dock.model().family(), DriveFamily::Sc750); // the dock follows the chosen family
        QCOMPARE(dock.readButton()->text(), QStringLiteral("Read Fault"));
        QCOMPARE(dock.model().headerData(ErrorLogModel::Code, Qt::Horizontal).toString(), QStringLiteral("Fault"));
        // On connecting the fault code was read: no fault, so no row, and the status line says so.
        QTRY_VERIFY_WITH_TIMEOUT(dock.statusText().startsWith(QStringLiteral("FAULTCODE 0")), kTimeoutMs);
        QCOMPARE(dock.model().rowCount(), 0);

        // A compile error is a row with its line.
        qobject_cast<app::Sc750ControllerMenu*>(ws.menus().at(1))->createProgram();
        editor::ProgramEditor* program = window.editor();
        program->setText(QStringLiteral("DIM a AS INTEGER\na = 1\nGOTO Nowhere\nEND\n"));
        QVERIFY(!ws.debugger().compile());
        QCOMPARE(dock.model().rowCount(), 1);
        QCOMPARE(cell(dock.model(), 0, ErrorLogModel::Severity), QStringLiteral("Compile"));
        QCOMPARE(cell(dock.model(), 0, ErrorLogModel::Line), QStringLiteral("3"));

        // The fourth line divides by zero at run time: F 4, the drive's message, line 4.
        program->setText(QStringLiteral("DIM a AS INTEGER\nDIM b AS INTEGER\nb = 0\na = 10 / b\nPRINT a\nEND\n"));
        ws.action(QStringLiteral("Run Program"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(dock.model(), QStringLiteral("F 4")) >= 0, kTimeoutMs);
        const int row = rowOf(dock.model(), QStringLiteral("F 4"));
        QVERIFY2(row == 0, qPrintable(rows(dock.model())));
        QCOMPARE(dock.model().entry(row).code, 244);
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Severity), QStringLiteral("Run-time error"));
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Message), QStringLiteral("DIVISION BY ZERO"));
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Line), QStringLiteral("4"));
        QVERIFY2(cell(dock.model(), row, ErrorLogModel::Hint).contains(QStringLiteral("divisor")),
                 qPrintable(cell(dock.model(), row, ErrorLogModel::Hint)));
        QVERIFY(dock.model().index(row, ErrorLogModel::Severity).data(Qt::DecorationRole).isValid());
        QVERIFY(dock.model()
                    .index(row, ErrorLogModel::Code)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("FAULTCODE 244")));
        QCOMPARE(ws.debugger().state(), app::Sc750Debugger::State::Faulted);

        // Another tab is current and the cursor elsewhere: activating the row shows line 4 of the program.
        window.editorArea()->tabs()->addEditor(QStringLiteral("other.bas"));
        QVERIFY(window.editor() != program);
        program->setCursorPosition(0, 0);
        emit dock.view()->activated(dock.model().index(row, ErrorLogModel::Line));
        QCOMPARE(window.editor(), program);
        QCOMPARE(cursorLine(program), 3);

        // Read Fault: the controller still shows F 4, stopped at line 4.
        dock.readHistory();
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(dock.model(), QStringLiteral("F 4"), ErrorLogModel::Origin::History) >= 0,
                                 kTimeoutMs);
        const int history = rowOf(dock.model(), QStringLiteral("F 4"), ErrorLogModel::Origin::History);
        QCOMPARE(cell(dock.model(), history, ErrorLogModel::Source), QStringLiteral("FAULTCODE"));
        QCOMPARE(cell(dock.model(), history, ErrorLogModel::Message), QStringLiteral("Run time error"));
        QCOMPARE(cell(dock.model(), history, ErrorLogModel::Line), QStringLiteral("4"));
        QVERIFY2(dock.statusText().contains(QStringLiteral("FAULTCODE 244")), qPrintable(dock.statusText()));

        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("sc750.csv"));
        QVERIFY(dock.exportTo(csv));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY2(text.contains(QStringLiteral("Run-time error,F 4,DIVISION BY ZERO,4,")), qPrintable(text));

        dock.clearHistory();
        QCOMPARE(dock.model().rowCount(), 0);

        // Back to the BDS5: its own log and buttons.
        window.connectDrive(app::ConnectionChoice::simulator(DriveFamily::Bds5));
        QCOMPARE(dock.model().family(), DriveFamily::Bds5);
        QCOMPARE(dock.readButton()->text(), QStringLiteral("Read History"));
    }

    void pmc960RefusalAndAsynchronousErrorAreDecoded() {
        MainWindow window;
        window.show();
        auto& ws = family_window::connectPmc960(window);
        QTRY_VERIFY_WITH_TIMEOUT(ws.isConnected(), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(ws.session()->state(), serialport::Pmc960Session::State::Ready, kTimeoutMs);
        app::ErrorLogDock& dock = *window.errorLogDock();
        dock.show();
        QCOMPARE(dock.model().family(), DriveFamily::Pmc960);
        QCOMPARE(dock.readButton()->text(), QStringLiteral("Read Last Error"));

        // Motion while the servodrive is not enabled (SM0 at power-up): the controller refuses it with #B6.
        app::TerminalWidget* terminal = window.terminal();
        terminal->setFocus();
        type(terminal, QStringLiteral("I4000+\r"));
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(dock.model(), QStringLiteral("#B6")) >= 0, kTimeoutMs);
        int row = rowOf(dock.model(), QStringLiteral("#B6"));
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Severity), QStringLiteral("Refused"));
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Message), QStringLiteral("Servodrive not enabled 'I4000+'"));
        QVERIFY2(cell(dock.model(), row, ErrorLogModel::Hint).contains(QStringLiteral("SM1 or SM2")),
                 qPrintable(cell(dock.model(), row, ErrorLogModel::Hint)));
        QVERIFY(dock.model()
                    .index(row, ErrorLogModel::Code)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("L2351")));

        // A long move, and ESTOP' asserted on the bench while it runs: #E0 arrives by itself.
        type(terminal, QStringLiteral("SM2\r"));
        type(terminal, QStringLiteral("I400000+\r"));
        app::Pmc960StatusDock* status = ws.statusDock();
        QTRY_VERIFY_WITH_TIMEOUT(status->value(QStringLiteral("position")).toInt() > 0, kTimeoutMs);
        auto* simulator = qobject_cast<serialport::SimulatorLink*>(ws.link());
        QVERIFY(simulator);
        simulator->control([](drive_core::SimulatorControls& bench) { bench.setMotionInput(false); });
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(dock.model(), QStringLiteral("#E0")) >= 0, kTimeoutMs);
        row = rowOf(dock.model(), QStringLiteral("#E0"));
        QVERIFY2(row == 0, qPrintable(rows(dock.model())));
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Severity), QStringLiteral("System"));
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Message), QStringLiteral("ESTOP' in motion"));
        QVERIFY(!cell(dock.model(), row, ErrorLogModel::Hint).isEmpty());
        QCOMPARE(dock.model().entry(row).level, ErrorLogModel::Level::Fault);

        // Read Last Error: the error-status buffer holds #E0 and where the axis was.
        dock.readHistory();
        QTRY_VERIFY_WITH_TIMEOUT(rowOf(dock.model(), QStringLiteral("#E0"), ErrorLogModel::Origin::History) >= 0,
                                 kTimeoutMs);
        row = rowOf(dock.model(), QStringLiteral("#E0"), ErrorLogModel::Origin::History);
        QCOMPARE(cell(dock.model(), row, ErrorLogModel::Source), QStringLiteral("last error (&)"));
        QVERIFY2(cell(dock.model(), row, ErrorLogModel::Message).contains(QStringLiteral("position ")),
                 qPrintable(cell(dock.model(), row, ErrorLogModel::Message)));
        QVERIFY2(dock.statusText().startsWith(QStringLiteral("Last error #E0")), qPrintable(dock.statusText()));

        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("pmc960.csv"));
        QVERIFY(dock.exportTo(csv));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY2(text.contains(QStringLiteral("Refused,#B6,Servodrive not enabled,,I4000+,")), qPrintable(text));
        dock.clearHistory();
        QCOMPARE(dock.model().rowCount(), 0);
    }
};

QTEST_MAIN(ErrorLogFamiliesTest)
#include "error_log_families_test.moc"
