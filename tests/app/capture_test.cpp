// Capture: everything the session sent and received is in the capture, the .CAP file holds the drive's
// text byte for byte, and a saved .CAP opens again unchanged — also where the terminal folds a record's or
// a tuning run's PLAY listing into one line.
#include "app_test_support.h"
#include "app/families/bds5/bds5_workspace.h"
#include "app/drive/capture_dock.h"
#include "app/drive/capture_log.h"
#include "families/bds5/drive_connection.h"
#include "app/main_window.h"
#include "app/drive/terminal_widget.h"
#include "families/bds5/record/play_terminal_fold.h"
#include "app/scope/scope_controller.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "families/bds5/tuning/tuning_runner.h"

#include "serialport/bds5_session.h"

#include <QAction>
#include <QFile>
#include <QMessageBox> // tuning_panel.h holds a QPointer to one
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using app::CaptureLog;
using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;
bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}
bool atPrompt(const MainWindow& window) { // RECORD and PLAY work at the interactive prompt
    return ready(window) && window.connection().session()->mode() == serialport::Bds5Mode::Interactive;
}

// The lines of text that are rows of sample values, as PLAY lists them.
int sampleLines(const QString& text) {
    int count = 0;
    for (const QString& line : text.split(QLatin1Char('\n')))
        if (app::PlayTerminalFold::isSampleLine(QString(line).remove(QLatin1Char('\r')))) ++count;
    return count;
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

        app::CaptureDock* dock = window.bds5().captureDock();
        QVERIFY(dock->startAction()->isEnabled());
        dock->startAction()->trigger();
        QVERIFY(window.bds5().captureLog().isCapturing());
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
        QVERIFY(!window.bds5().captureLog().isCapturing());

        const CaptureLog& log = window.bds5().captureLog();
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
        QCOMPARE(window.bds5().captureLog().loadCap(path), QString());
        dock->setView(app::CaptureDock::View::AsSaved);
        QTRY_VERIFY(dock->shownText().startsWith(QStringLiteral("P \"CAPTURED\"\nCAPTURED\n-->P 7*6")));
        QVERIFY(!loaded.loadCap(dir.filePath(QStringLiteral("missing.cap"))).isEmpty());
    }

    // Issue 19 (13): each Scope record put its PLAY listing, a line per sample, in the terminal.
    void aRecordsPlayListingIsOneTerminalLineAndWholeInTheCapture() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(atPrompt(window), kDriveTimeoutMs);
        window.bds5().captureDock()->startAction()->trigger();

        serialport::Bds5RecordPlan plan;
        plan.samples = 40;
        plan.intervalMs = 2;
        plan.variables = {QStringLiteral("VCMD"), QStringLiteral("VFB")};
        QSignalSpy shown(&window.scopeController(), &app::ScopeController::captureShown);
        window.scopeController().record(plan);
        QVERIFY(shown.wait(kDriveTimeoutMs));
        QCOMPARE(window.scopeController().lastCapture()->sampleCount(), std::size_t(40)); // the scope has all

        // The terminal: the PLAY echo, one line for the listing, the prompt.
        const QString terminal = window.terminal()->text();
        QVERIFY2(terminal.contains(QStringLiteral("-->PLAY\nPLAY: 40 samples \u2192 Scope\n-->")),
                 qPrintable(terminal.right(600)));
        QCOMPARE(sampleLines(terminal), 0);
        QCOMPARE(terminal.count(QStringLiteral("RECORD 40 2 VCMD VFB")), 1); // RECORD's echo, not PLAY's header
        QVERIFY(!window.terminal()->isFolding());

        // The capture keeps what the drive sent: PLAY's header and every sample.
        const QString cap = QString::fromLatin1(window.bds5().captureLog().capBytes());
        const qsizetype play = cap.indexOf(QStringLiteral("PLAY\r\nRECORD 40 2 VCMD VFB\r\n"));
        QVERIFY2(play >= 0, qPrintable(cap.right(600)));
        const qsizetype prompt = cap.indexOf(QStringLiteral("-->"), play);
        QVERIFY(prompt > play);
        QCOMPARE(sampleLines(cap.mid(play, prompt - play)), 40);

        // Typed by the user, PLAY lists every sample in the terminal, as the drive's own terminal would.
        QTest::keyClicks(window.terminal(), QStringLiteral("PLAY"));
        QTest::keyClick(window.terminal(), Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(sampleLines(window.terminal()->text()) == 40 && atPrompt(window), kDriveTimeoutMs);
    }

    // Issue 19 (13): each tuning run did the same.
    void aTuningRunsPlayListingIsOneTerminalLine() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(atPrompt(window), kDriveTimeoutMs);
        app::TuningPanel* panel = window.scopeController().tuningPanel();
        app::TuningRunner& runner = panel->runner<app::TuningRunner>();
        // The factory PMAX/PMIN (+-100 counts) stop a jog at once (ERR 23): PLIM off, then enable.
        runner.setGain(QStringLiteral("PLIM"), 0);
        window.connection().sendCommand(QStringLiteral("EN"));
        QTRY_VERIFY_WITH_TIMEOUT(atPrompt(window), kDriveTimeoutMs);
        app::TestMove move;
        move.amplitude = 200;
        move.durationMs = 25; // a short run: 50 samples to list
        app::setTestMove(*panel, move);
        QSignalSpy runs(&runner, &app::TuningRunner::runFinished);
        runner.runOnce();
        QVERIFY(runs.wait(kDriveTimeoutMs));

        const int samples = int(runner.runs().constFirst().capture.sampleCount());
        QVERIFY(samples > 1);
        const QString terminal = window.terminal()->text();
        QVERIFY2(terminal.contains(QStringLiteral("-->PLAY\nPLAY: %1 samples \u2192 Tuning panel\n-->").arg(samples)),
                 qPrintable(terminal.right(600)));
        QCOMPARE(sampleLines(terminal), 0);
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
