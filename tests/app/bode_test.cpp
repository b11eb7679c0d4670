// Frequency response and polled chart against the simulated BDS5, asserting what a user sees: after TUNE 30 2
// the Bode view of a velocity step reads a -3 dB bandwidth near 30 Hz on a plot that is not blank; Watch
// Variables polls PFB while J 100 runs, the chart's values rise, the label shows a positive rate, and Stop
// puts no more P on the wire.
#include "app_test_support.h"
#include "families/bds5/drive_connection.h"
#include "app/main_window.h"
#include "app/scope/bode_view.h"
#include "app/scope/scope_controller.h"
#include "app/tuning/tuning_panel.h"
#include "families/bds5/tuning/bds5_tuning_controls.h"
#include "families/bds5/tuning/tuning_runner.h"
#include "app/scope/variable_watcher.h"
#include "app/scope/watch_view.h"

#include <qcustomplot.h>

#include <QDialogButtonBox>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;
using app_test::driveReady;

int distinctColours(const QImage& image) {
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2) colours.insert(image.pixel(x, y));
    return int(colours.size());
}

struct Window {
    MainWindow window;
    Window() {
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
    }
    bool enabled() {
        if (!QTest::qWaitFor([this] { return driveReady(window); }, kDriveTimeoutMs)) return false;
        window.scopeController().tuningRunner().setGain(QStringLiteral("PLIM"), 0); // PMAX/PMIN off
        window.connection().sendCommand(QStringLiteral("EN"));
        return QTest::qWaitFor([this] { return driveReady(window); }, kDriveTimeoutMs);
    }
};
} // namespace

class BodeTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskBodeTest"));
    }

    void tune30Hz2GivesABodeBandwidthNear30Hz() {
        Window w;
        QVERIFY(w.enabled());
        app::ScopeController& scope = w.window.scopeController();
        app::TuningRunner& runner = scope.tuningRunner();
        // The velocity loop alone (PL OFF) and a command that steps within a millisecond, as for the step test.
        runner.setGain(QStringLiteral("PL"), 0);
        // ACC may not pass AMAX (L2186), which changes only while disabled (L2180).
        for (const char* line : {"DIS", "AMAX=1000000", "ACC=1000000", "EN"})
            w.window.connection().sendCommand(QString::fromLatin1(line));
        app::TestMove move;
        move.kind = app::TestMove::Kind::FrequencyStep;
        move.amplitude = 100;
        move.durationMs = 400;
        app::setTestMove(*scope.tuningPanel(), move);
        QSignalSpy runs(&runner, &app::TuningRunner::runFinished);
        runner.tune(30, 2);
        QVERIFY(runs.wait(2 * kDriveTimeoutMs));

        app::BodeView* bode = scope.frequencyResponse();
        QVERIFY(bode && bode->isVisible());
        const scope::FrequencyResponse& r = bode->response();
        QCOMPARE(r.status, scope::FrequencyResponse::Status::Ok);
        QVERIFY2(r.bandwidth_hz, qPrintable(bode->summary()));
        qInfo("TUNE 30 2: Bode -3 dB bandwidth %.1f Hz; %s", *r.bandwidth_hz, qPrintable(bode->summary()));
        QVERIFY2(*r.bandwidth_hz > 15 && *r.bandwidth_hz < 60, qPrintable(QString::number(*r.bandwidth_hz)));
        QVERIFY(bode->summary().contains(QStringLiteral("Hz")));
        QCOMPARE(bode->plot()->graphCount(), 2);
        QVERIFY(bode->plot()->graph(0)->dataCount() >= 5);
        QVERIFY(QTest::qWaitForWindowExposed(bode));
        bode->plot()->replot(QCustomPlot::rpImmediateRefresh);
        QVERIFY2(distinctColours(bode->plot()->grab().toImage()) > 20, "the Bode plot is blank");

        // Esc closes it, wherever the focus is (the plot takes it), and so does its Close button.
        bode->plot()->setFocus();
        QTest::keyClick(bode->plot(), Qt::Key_Escape);
        QTRY_VERIFY(!bode->isVisible());
        bode->show();
        auto* close = bode->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Close);
        QVERIFY(close && close->isVisible());
        close->click();
        QVERIFY(!bode->isVisible());
    }

    void watchingPfbWhileJoggingShowsItRiseAndStopEndsThePolls() {
        Window w;
        QVERIFY(w.enabled());
        w.window.connection().sendCommand(QStringLiteral("J 100"));
        app::WatchView* watch = w.window.scopeController().watchVariables();
        QSignalSpy shown(&w.window.connection(), &app::DriveConnection::shownReceived);
        watch->watch({QStringLiteral("PFB")});
        const app::VariableWatcher& watcher = watch->watcher();
        QTRY_VERIFY_WITH_TIMEOUT(watcher.store().channel(0).samples.size() >= 6, kDriveTimeoutMs);
        // The polls are quiet: what the terminal shows holds none of them (the generic watch over the
        // BDS5's DriveSession sends them as the old BDS5-only source did).
        QByteArray terminal;
        for (const QList<QVariant>& s : shown) terminal += s.at(0).toByteArray();
        QVERIFY2(!terminal.contains("P PFB"), terminal.constData());
        const auto& samples = watcher.store().channel(0).samples;
        QVERIFY2(samples.back().value > samples.front().value,
                 qPrintable(QStringLiteral("%1 -> %2").arg(samples.front().value).arg(samples.back().value)));
        QVERIFY(watcher.rate_hz() > 0);
        QVERIFY2(watch->rateLabel().startsWith(QStringLiteral("polled, ")) &&
                     watch->rateLabel().endsWith(QStringLiteral("samples/s")),
                 qPrintable(watch->rateLabel()));
        qInfo("%s", qPrintable(watch->rateLabel()));
        QVERIFY(watch->plot()->graph(0)->dataCount() >= 6);

        watch->stop();
        // From here on no poll goes out. A BDS5 watcher polls again as soon as an answer comes, on the session's
        // one queue: five commands queued behind Stop and answered leave no room for a poll that was missed.
        serialport::Bds5Session* session = w.window.connection().session();
        QSignalSpy sent(session, &serialport::Bds5Session::rawSent);
        QSet<quint64> markers;
        for (int i = 0; i < 5; ++i) markers.insert(session->send(QStringLiteral("P 0"), serialport::Bds5Session::Echo::Quiet));
        connect(session, &serialport::Bds5Session::finished, &w.window,
                [&markers](quint64 id, const serialport::Bds5Response&) { markers.remove(id); });
        QTRY_VERIFY_WITH_TIMEOUT(markers.isEmpty(), kDriveTimeoutMs);
        for (const QList<QVariant>& s : sent)
            QVERIFY2(!s.at(0).toByteArray().startsWith("P PFB"), "a poll went out after Stop");
        QVERIFY(sent.count() >= 5);
        QVERIFY(!watcher.isRunning());
        w.window.connection().sendCommand(QStringLiteral("J 0"));
    }
};

QTEST_MAIN(BodeTest)
#include "bode_test.moc"
