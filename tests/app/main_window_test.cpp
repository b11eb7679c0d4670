// MainWindow against the simulated BDS5: what a user sees on start-up and after typing in the terminal; and
// that every family starts with its own sample program (servodesk --drive sc750 showed the BDS5's hello.bds).
#include "app_test_support.h"
#include "families/bds5/drive_connection.h"
#include "app/drive/terminal_widget.h"
#include "app/editing/editor_area.h"
#include "app/editing/editor_tabs.h"
#include "app/main_window.h"

#include "drive_core/bds5/bds5_drive.h"
#include "editor/language_support.h"
#include "editor/program_editor.h"
#include "resources/resources.h"

#include <QFile>
#include <QLabel>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

using app::MainWindow;
using drive_core::DriveFamily;

namespace {
using app_test::kDriveTimeoutMs;
const QString kPrompt = QStringLiteral("-->");

QString labelText(const MainWindow& window, const char* name) {
    const auto* label = window.statusBar()->findChild<QLabel*>(QLatin1String(name));
    return label ? label->text() : QStringLiteral("<no %1>").arg(QLatin1String(name));
}

QStringList terminalLines(const MainWindow& window) {
    return window.terminal()->text().split(QLatin1Char('\n'));
}

bool driveReady(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}
} // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // never touch the user's settings
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDesk"));
    }

    void opensWithTheSampleProgram() {
        MainWindow window;
        resources::initialize();
        QFile sample(resources::kSampleProgram);
        QVERIFY(sample.open(QIODevice::ReadOnly));
        const QString expected = QString::fromUtf8(sample.readAll());
        QCOMPARE(window.editor()->text(), expected);
        QVERIFY(window.editor()->text().contains(QStringLiteral("\n10$")));
        QVERIFY(window.editor()->text().contains(QStringLiteral("P \"HELLO, WORLD\"")));
        QVERIFY(!window.editor()->isModified());
        QVERIFY(window.editor()->filePath().isEmpty()); // saving asks for a name, never writes the resource
        QVERIFY(window.windowTitle().startsWith(QStringLiteral("hello.bds")));
    }

    void eachFamilyStartsWithItsOwnSampleProgram_data() {
        QTest::addColumn<DriveFamily>("family");
        QTest::addColumn<QString>("resource");
        QTest::addColumn<QString>("name");
        QTest::addColumn<QStringList>("shown"); // lines of the family's language the user sees
        QTest::newRow("BDS5") << DriveFamily::Bds5 << resources::kSampleProgram << QStringLiteral("hello.bds")
                              << QStringList{QStringLiteral("10$"), QStringLiteral("P \"HELLO, WORLD\"")};
        QTest::newRow("SC750") << DriveFamily::Sc750 << resources::kSc750SampleProgram << QStringLiteral("hello.bas")
                               << QStringList{QStringLiteral("PRINT \"Hello, world\""), QStringLiteral("GO.INCR"),
                                              QStringLiteral("END ' Main Program")};
        QTest::newRow("PMC-960") << DriveFamily::Pmc960 << resources::kPmc960SampleProgram
                                 << QStringLiteral("hello.mpl")
                                 << QStringList{QStringLiteral("@H_Hello"), QStringLiteral("I+,"),
                                                QStringLiteral("G!")};
    }

    // As main() does for servodesk --drive FAMILY: the window made for the family, then connected to it.
    void eachFamilyStartsWithItsOwnSampleProgram() {
        QFETCH(DriveFamily, family);
        QFETCH(QString, resource);
        QFETCH(QString, name);
        QFETCH(QStringList, shown);
        MainWindow window(family);
        window.connectDrive(app::ConnectionChoice::simulator(family));
        window.show();

        QFile sample(resource);
        QVERIFY2(sample.open(QIODevice::ReadOnly), qPrintable(resource));
        QCOMPARE(window.editorArea()->tabs()->count(), 1);
        const QString text = window.editor()->text();
        QCOMPARE(text, QString::fromUtf8(sample.readAll()));
        for (const QString& line : shown) QVERIFY2(text.contains(line), qPrintable(line));
        if (family != DriveFamily::Bds5) QVERIFY(!text.contains(QStringLiteral("HELLO, WORLD"))); // not hello.bds
        QVERIFY(window.windowTitle().startsWith(name));
        QCOMPARE(window.editorArea()->tabs()->tabText(0), name);
        QVERIFY(!window.editor()->isModified());
        QVERIFY(window.editor()->filePath().isEmpty()); // saving asks for a name, never writes the resource

        // In its language's colours: the first line shown above is styled, not default text (the SC750's
        // sample once lost its lexer to the tab's plain-text set-up and showed black proportional text).
        editor::ProgramEditor* ed = window.editor();
        QVERIFY(editor::LanguageSupport::of(ed) != nullptr);
        QVERIFY(ed->lexer() != nullptr);
        ed->SendScintilla(QsciScintilla::SCI_COLOURISE, 0L, -1L);
        const long at = long(text.toUtf8().indexOf(shown.first().toUtf8()));
        QVERIFY(ed->SendScintilla(QsciScintilla::SCI_GETSTYLEAT, at) != 0);
    }

    void terminalShowsSignOnThenHelloWorld() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        const QString signOn = QString::fromLatin1(drive_core::bds5::kSignOn);
        QTRY_VERIFY_WITH_TIMEOUT(window.terminal()->text().contains(signOn), kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(terminalLines(window).last() == kPrompt && driveReady(window),
                                 kDriveTimeoutMs);
        QCOMPARE(labelText(window, "linkLabel"), QStringLiteral("Simulated BDS5"));
        QCOMPARE(labelText(window, "portLabel"), QStringLiteral("9600 baud")); // "Simulated BDS5" once, not twice
        QVERIFY2(labelText(window, "modeLabel").contains(QStringLiteral("Interactive -->")),
                 qPrintable(labelText(window, "modeLabel")));
        QVERIFY(labelText(window, "stateLabel").contains(QStringLiteral("Ready")));

        QTest::keyClicks(window.terminal(), QStringLiteral("P \"HELLO, WORLD\""));
        QTest::keyClick(window.terminal(), Qt::Key_Return);

        // The drive echoes the line after the prompt, prints the text on a line of its own, prompts again.
        const QString echo = QStringLiteral("-->P \"HELLO, WORLD\"");
        const QString hello = QStringLiteral("HELLO, WORLD");
        QTRY_VERIFY_WITH_TIMEOUT(terminalLines(window).contains(hello) &&
                                     terminalLines(window).last() == kPrompt,
                                 kDriveTimeoutMs);
        const QStringList lines = terminalLines(window);
        const qsizetype echoAt = lines.indexOf(echo);
        QVERIFY2(echoAt >= 0, qPrintable(window.terminal()->text()));
        QCOMPARE(lines.value(echoAt + 1), hello);
        QCOMPARE(lines.value(echoAt + 2), kPrompt);
        QCOMPARE(lines.size(), echoAt + 3);
        QTRY_VERIFY_WITH_TIMEOUT(labelText(window, "modeLabel").contains(QStringLiteral("Interactive")),
                                 kDriveTimeoutMs);
    }

    void linkErrorsShowInStatusBarAndTerminal() {
        MainWindow window;
        window.connectDrive(
            app::ConnectionChoice::serialPort(QStringLiteral("/nonexistent/ttyServoDesk"), 9600));
        QVERIFY(!window.connection().isConnected());
        QVERIFY2(window.statusBar()->currentMessage().contains(QStringLiteral("/nonexistent/ttyServoDesk")),
                 qPrintable(window.statusBar()->currentMessage()));
        QVERIFY(window.terminal()->text().contains(QStringLiteral("[/nonexistent/ttyServoDesk")));
        QVERIFY(labelText(window, "stateLabel").contains(QStringLiteral("Disconnected")));
        QCOMPARE(labelText(window, "linkLabel"), QStringLiteral("/nonexistent/ttyServoDesk 9600 8N1"));
    }

    void disconnectClosesTheLink() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        QTRY_VERIFY_WITH_TIMEOUT(driveReady(window), kDriveTimeoutMs);
        window.connection().disconnectDrive();
        QVERIFY(!window.connection().isConnected());
        QVERIFY(labelText(window, "stateLabel").contains(QStringLiteral("Disconnected")));
        QTest::keyClick(window.terminal(), Qt::Key_Return); // typing while disconnected says so, no crash
        QVERIFY(window.terminal()->text().contains(QStringLiteral("[Not connected")));
    }
};

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
