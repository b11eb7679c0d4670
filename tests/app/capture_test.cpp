// Capture: everything the session sent and received is in the capture, the .CAP file holds the drive's
// text byte for byte, and a saved .CAP opens again unchanged.
#include "app/drive/capture_dock.h"
#include "app/drive/capture_log.h"
#include "app/drive/drive_connection.h"
#include "app/main_window.h"
#include "app/drive/terminal_widget.h"

#include "serialport/bds5_session.h"

#include <QAction>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using app::CaptureLog;
using app::MainWindow;

namespace {
constexpr int kDriveTimeoutMs = 30000; // generous: a loaded machine has been seen to stall every process for 8 s
bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}
} // namespace

class CaptureTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskCaptureTest"));
        QSettings().clear();
    }

    void captureHoldsTheSessionAndRoundTripsCap() {
        MainWindow window;
        QByteArray sent, received; // what crossed the link while capturing, seen independently
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);

        app::CaptureDock* dock = window.captureDock();
        QVERIFY(dock->startAction()->isEnabled());
        dock->startAction()->trigger();
        QVERIFY(window.captureLog().isCapturing());
        connect(&window.connection(), &app::DriveConnection::rawSent, &window, [&sent](const QByteArray& b) { sent += b; });
        connect(&window.connection(), &app::DriveConnection::rawReceived, &window,
                [&received](const QByteArray& b) { received += b; });
        QTest::keyClicks(window.terminal(), QStringLiteral("P \"CAPTURED\""));
        QTest::keyClick(window.terminal(), Qt::Key_Return);
        window.connection().sendCommand(QStringLiteral("P 7*6"));
        QTRY_VERIFY_WITH_TIMEOUT(window.terminal()->text().endsWith(QStringLiteral("42\n-->")) && ready(window),
                                 kDriveTimeoutMs);
        QTest::keyClick(window.terminal(), Qt::Key_X, Qt::ControlModifier); // ^X: not echoed by the drive
        QVERIFY(sent.endsWith('\x18')); // an urgent byte is written at once
        dock->stopAction()->trigger();
        QVERIFY(!window.captureLog().isCapturing());

        const CaptureLog& log = window.captureLog();
        QCOMPARE(log.capBytes(), received);
        QVERIFY(log.capBytes().contains("P \"CAPTURED\"\r\nCAPTURED\r\n-->P 7*6\r\n          42\r\n-->"));
        QCOMPARE(log.sentBytes(), sent.size());
        QCOMPARE(sent, QByteArray("P \"CAPTURED\"\rP 7*6\r\x18"));
        const QString transcript = log.transcript();
        // What went out, in order: the transcript starts a new entry after a pause on the wire, and how the
        // typed line splits into entries depends on the host's timing (a loaded machine paused 0.3 s before
        // the Return), so the entries are read back joined.
        QString out;
        for (const QString& line : transcript.split(QLatin1Char('\n')))
            if (const qsizetype at = line.indexOf(QStringLiteral("  >  ")); at >= 0) out += line.mid(at + 5);
        QCOMPARE(out, QStringLiteral("P \"CAPTURED\"<CR>P 7*6<CR><^X>"));
        QVERIFY(transcript.contains(QStringLiteral("<  CAPTURED<CR><LF>")));

        // What the user sees in the Capture view.
        dock->show();
        dock->raise();
        dock->setView(app::CaptureDock::View::AsSaved);
        QTRY_VERIFY(dock->shownText().contains(QStringLiteral("-->P 7*6\n          42\n-->")));
        QVERIFY(!dock->shownText().contains(QLatin1Char('\r')));
        QVERIFY(dock->sizeText().contains(QStringLiteral("%1 bytes received").arg(received.size())));
        dock->setView(app::CaptureDock::View::Transcript);
        QTRY_VERIFY(dock->shownText().contains(QStringLiteral("<^X>")));

        // Save, open again: the same bytes, shown the same way.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("session.cap"));
        QCOMPARE(log.saveCap(path), QString());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), received);
        CaptureLog loaded;
        QCOMPARE(loaded.loadCap(path), QString());
        QCOMPARE(loaded.capBytes(), log.capBytes());
        QCOMPARE(window.captureLog().loadCap(path), QString());
        dock->setView(app::CaptureDock::View::AsSaved);
        QTRY_VERIFY(dock->shownText().startsWith(QStringLiteral("P \"CAPTURED\"\nCAPTURED\n-->P 7*6")));
        QVERIFY(!loaded.loadCap(dir.filePath(QStringLiteral("missing.cap"))).isEmpty());
    }

    void startClearsAndNothingIsKeptWhenStopped() {
        CaptureLog log;
        log.addReceived("before");
        QCOMPARE(log.receivedBytes(), 0);
        log.start();
        log.addReceived("ONE\r\n");
        log.addSent("P 1\r");
        log.stop();
        log.addReceived("after");
        QCOMPARE(log.capBytes(), QByteArray("ONE\r\n"));
        log.start(); // START CAPTURE clears the buffer (L1080)
        QCOMPARE(log.capBytes(), QByteArray());
        QCOMPARE(log.sentBytes(), 0);
    }
};

QTEST_MAIN(CaptureTest)
#include "capture_test.moc"
