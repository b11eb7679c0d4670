// The error log (issue 7): ERR HIST parsed into rows with severity, catalog text and fix hint; errors the
// drive reports while the IDE watches, go-to-line for a program error, ERR CLR and CSV export — against the
// simulated BDS5. Plus the scanner that tells a drive's error from a listing that merely looks like one.
#include "app_test_support.h"
#include "families/bds5/drive_connection.h"
#include "app/editing/editor_area.h"
#include "app/errors/error_log_dock.h"
#include "app/errors/error_log_model.h"
#include "app/errors/error_stream_scanner.h"
#include "app/main_window.h"

#include "editor/program_editor.h"
#include "serialport/bds5_session.h"

#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using app::ErrorLogModel;
using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;

bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}

QStringList codes(const ErrorLogModel& model, ErrorLogModel::Origin origin) {
    QStringList list;
    for (int row = 0; row < model.rowCount(); ++row)
        if (model.entry(row).origin == origin) list << QString::number(model.entry(row).code);
    return list;
}
} // namespace

class ErrorLogTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskErrorLogTest"));
        QSettings().clear();
    }

    void theScannerTakesOnlyBellLedLines() {
        app::ErrorStreamScanner scanner;
        QVERIFY(scanner.feed("ERR HIST\r\nERR 80 INVALID INSTRUCTION\r\n-->").isEmpty());
        auto found = scanner.feed("\aERR 92 LINE 3 'X1=5/X2'");
        QVERIFY(found.isEmpty()); // not complete yet
        found = scanner.feed("                 ZERO DIVIDE\r\n-->");
        QCOMPARE(found.size(), 1);
        QCOMPARE(found.first().code, 92);
        QCOMPARE(found.first().programLine, 3);
        const auto history = app::ErrorStreamScanner::parseHistory(
            QStringLiteral("ERR 80 INVALID INSTRUCTION\r\nERR 199 DRIVE POWERED UP\r\n"));
        QCOMPARE(history.size(), 2);
        QCOMPARE(history[1].message, QStringLiteral("DRIVE POWERED UP"));
    }

    void errHistIsParsedIntoRowsAndLiveErrorsArrive() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::ErrorLogDock& dock = *window.errorLogDock();
        dock.show();
        // A program whose third line divides by zero, loaded and run as a user would.
        editor::ProgramEditor* editor = window.editor();
        editor->setText(QStringLiteral("; ZERO.BDS\n1$\n  X2=0\n\n  X1=5/X2 ; oops\n  B\n"));
        auto* session = window.connection().session();
        session->send(QStringLiteral(">BDS"));
        for (const char* line : {"1$", "X2=0", "X1=5/X2", "B"}) session->send(QString::fromLatin1(line));
        session->sendEscape();
        for (const char* line : {"FOO", "GOTO 1", "RUN 1"}) window.connection().sendCommand(QString::fromLatin1(line));
        QTRY_VERIFY_WITH_TIMEOUT(codes(dock.model(), ErrorLogModel::Origin::Reported).size() == 3, kDriveTimeoutMs);
        QCOMPARE(codes(dock.model(), ErrorLogModel::Origin::Reported), (QStringList{"92", "52", "80"}));
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);

        dock.readHistory();
        QTRY_VERIFY_WITH_TIMEOUT(!codes(dock.model(), ErrorLogModel::Origin::History).isEmpty(), kDriveTimeoutMs);
        const QStringList history = codes(dock.model(), ErrorLogModel::Origin::History);
        QVERIFY2(history.startsWith(QStringLiteral("92")) && history.contains(QStringLiteral("199")),
                 qPrintable(history.join(' ')));
        QVERIFY2(dock.statusText().startsWith(QStringLiteral("ERR HIST: ")), qPrintable(dock.statusText()));
        // What the user sees in the first history row: severity, message and the manual's hint.
        const int row = int(codes(dock.model(), ErrorLogModel::Origin::Reported).size());
        QCOMPARE(dock.model().index(row, ErrorLogModel::Severity).data().toString(), QStringLiteral("Break"));
        QCOMPARE(dock.model().index(row, ErrorLogModel::Message).data().toString(), QStringLiteral("ZERO DIVIDE"));
        QCOMPARE(dock.model().index(row, ErrorLogModel::Source).data().toString(), QStringLiteral("history #1"));
        QVERIFY(!dock.model().index(row, ErrorLogModel::Hint).data().toString().isEmpty());
        QVERIFY(dock.model().index(row, ErrorLogModel::Severity).data(Qt::DecorationRole).isValid());

        // Go to line: the drive's line 3 is the editor's line 5 (comment and blank lines were not sent).
        const QModelIndex reported = dock.model().index(0, ErrorLogModel::Line);
        QCOMPARE(reported.data().toInt(), 3);
        emit dock.view()->activated(reported);
        int line = -1, column = -1;
        editor->getCursorPosition(&line, &column);
        QCOMPARE(line, 4);

        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("errors.csv"));
        QVERIFY(dock.exportTo(csv));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY(text.startsWith(QStringLiteral("severity,code,message,line,entry,source,hint\n")));
        QVERIFY(text.contains(QStringLiteral("Break,92,ZERO DIVIDE,3,")));

        dock.clearHistory();
        QTRY_VERIFY_WITH_TIMEOUT(dock.statusText() == QStringLiteral("The drive's error history is empty."),
                                 kDriveTimeoutMs);
        QCOMPARE(dock.model().rowCount(), 0);
    }
};

QTEST_MAIN(ErrorLogTest)
#include "error_log_test.moc"
