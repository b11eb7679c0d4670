// DriveTimeout: a session's time-out counts the drive's time where the link has a drive clock, so a host
// that stalls the simulator's thread does not make a drive that never ran look silent (flake-hunt: "no
// prompt from the drive within 175 ms" in bench.bds5_download and app.variable_browser under load).
#include "serialport/drive_timeout.h"
#include "serialport/link.h"

#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <functional>
#include <utility>

namespace {

// A link whose drive clock the test moves by hand: a drive that has not run while the host's timers did.
class ClockLink final : public serialport::Link {
public:
    void open() override { m_open = true; }
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    void write(const QByteArray&) override {}
    QString description() const override { return QStringLiteral("clock"); }
    int baudRate() const override { return 9600; }
    std::optional<double> driveClockMs() const override {
        if (onRead) onRead();
        return clock;
    }

    std::optional<double> clock = 0.0;
    std::function<void()> onRead; // as the simulator's worker: what the drive sent is posted before the clock

private:
    bool m_open = true;
};

// Waits for a plain wall-clock timer of ms to fire: a positive event, after which a DriveTimeout of fewer
// ms has had every chance to fire on the wall clock (timers of one thread fire in the order they expire).
void waitWall(int ms) {
    QTimer later;
    later.setSingleShot(true);
    QSignalSpy fired(&later, &QTimer::timeout);
    later.start(ms);
    QVERIFY(fired.wait(30000));
}

} // namespace

class DriveTimeoutTest : public QObject {
    Q_OBJECT
private slots:
    void aDriveThatDidNotRunHasNotTimedOut() {
        ClockLink link;
        serialport::DriveTimeout timeout(link);
        QSignalSpy expired(&timeout, &serialport::DriveTimeout::timeout);
        timeout.start(20);
        waitWall(120); // six time-outs of wall time, none of drive time
        QCOMPARE(expired.count(), 0);
        QVERIFY(timeout.isActive());
        link.clock = 10.0; // half of it
        waitWall(60);
        QCOMPARE(expired.count(), 0);
        link.clock = 25.0; // the drive has run 25 ms without answering: that is silence
        QVERIFY(expired.wait(30000));
        QCOMPARE(expired.count(), 1);
        QVERIFY(!timeout.isActive());
    }

    void aRealPortTimesOutOnTheWallClock() {
        ClockLink link;
        link.clock.reset(); // no drive clock: a real port
        serialport::DriveTimeout timeout(link);
        QSignalSpy expired(&timeout, &serialport::DriveTimeout::timeout);
        timeout.start(20);
        QVERIFY(expired.wait(30000));
        QCOMPARE(expired.count(), 1);
    }

    void anAnswerPostedWithTheClockWinsTheRace() {
        ClockLink link;
        serialport::DriveTimeout timeout(link);
        QSignalSpy expired(&timeout, &serialport::DriveTimeout::timeout);
        timeout.start(20);
        link.clock = 100.0; // the drive ran past the time-out, and answered on its last tick
        bool answered = false;
        bool posted = false;
        link.onRead = [&] {
            if (std::exchange(posted, true)) return;
            QMetaObject::invokeMethod(
                &timeout,
                [&] {
                    timeout.stop(); // the session has its answer
                    answered = true;
                },
                Qt::QueuedConnection);
        };
        QTRY_VERIFY_WITH_TIMEOUT(answered, 30000);
        waitWall(60);
        QCOMPARE(expired.count(), 0);
    }

    void aClosedLinkTimesOutAtOnce() {
        ClockLink link;
        link.close();
        serialport::DriveTimeout timeout(link);
        QSignalSpy expired(&timeout, &serialport::DriveTimeout::timeout);
        timeout.start(20);
        QVERIFY(expired.wait(30000));
    }
};

QTEST_GUILESS_MAIN(DriveTimeoutTest)
#include "drive_timeout_test.moc"
