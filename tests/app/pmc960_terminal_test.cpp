// The Terminal dock follows the active family (issue 9): with the PMC-960 connected, what is typed there
// reaches the simulated controller and its echo and prompt appear, the status polls' answers do not; Esc
// is Stop. With the SC750 the terminal says where its program's I/O is instead.
#include "app/main_window.h"
#include "families/pmc960/pmc960_workspace.h"
#include "app/drive/terminal_widget.h"

#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using app::MainWindow;
using app::Pmc960Workspace;
using drive_core::DriveFamily;

namespace {
constexpr int kTimeoutMs = 20000;

void type(app::TerminalWidget* terminal, const QString& text) {
    for (const QChar c : text) {
        if (c == QLatin1Char('\r')) QTest::keyClick(terminal, Qt::Key_Return);
        else QTest::keyClicks(terminal, QString(c));
    }
}
} // namespace

class Pmc960TerminalTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskPmc960TerminalTest"));
        QSettings().clear();
    }

    void typedCommandsReachTheController() {
        MainWindow window;
        window.show();
        window.connectDrive(app::ConnectionChoice::simulator(DriveFamily::Pmc960));
        auto* ws = static_cast<Pmc960Workspace*>(window.workspace(DriveFamily::Pmc960));
        QTRY_VERIFY_WITH_TIMEOUT(ws->isConnected(), kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(ws->session()->state(), serialport::Pmc960Session::State::Ready, kTimeoutMs);
        app::TerminalWidget* terminal = window.terminal();
        terminal->setFocus();
        type(terminal, QStringLiteral("A2500\r"));
        type(terminal, QStringLiteral("A?"));
        // The controller's echo, its answer and its prompt, as a terminal on the controller would show them.
        QTRY_VERIFY_WITH_TIMEOUT(terminal->text().contains(QStringLiteral("A2500")), kTimeoutMs);
        QTRY_VERIFY2_WITH_TIMEOUT(terminal->text().contains(QStringLiteral("2500\n= }")) ||
                                      terminal->text().contains(QStringLiteral("A?2500")),
                                  qPrintable(terminal->text()), kTimeoutMs);
        QVERIFY2(terminal->text().contains(QLatin1Char('}')), qPrintable(terminal->text()));
        // The status panel's polls (position, following error...) are not in the terminal.
        QVERIFY2(!terminal->text().contains(QChar(0x1D)), qPrintable(terminal->text()));

        // Esc is Stop: a jog typed at the terminal ends.
        QSignalSpy messages(ws, &app::FamilyWorkspace::message);
        QTest::keyClick(terminal, Qt::Key_Escape);
        QTRY_VERIFY_WITH_TIMEOUT(!messages.isEmpty(), kTimeoutMs);
        QVERIFY(messages.first().at(0).toString().contains(QStringLiteral("ESC")));
    }

    void theSc750SaysWhereItsProgramIoIs() {
        MainWindow window;
        window.show();
        window.connectDrive(app::ConnectionChoice::simulator(DriveFamily::Sc750));
        app::TerminalWidget* terminal = window.terminal();
        terminal->setFocus();
        type(terminal, QStringLiteral("x"));
        QTRY_VERIFY_WITH_TIMEOUT(terminal->text().contains(QStringLiteral("Output window")), kTimeoutMs);
    }
};

QTEST_MAIN(Pmc960TerminalTest)
#include "pmc960_terminal_test.moc"
