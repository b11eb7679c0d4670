// Stop while a program download runs, for each family (issue 11): the stop byte — ^X for the BDS5, Ctrl C
// for the SC750, ESC for the PMC-960 — is written to the link during the stop request itself, ahead of the
// download's next line or frame, so it reaches the link 0 ms of drive time after the request (the promise:
// within 50 ms); no program line or frame goes out after it; the download ends cancelled with a reason that
// says what the drive holds, never successful; and the drive shows it took the stop.
#include "in_process_drive_link.h"

#include "drive_core/sc750/sc750_compiler.h"
#include "serialport/bds5_download.h"
#include "serialport/pmc960_download.h"
#include "serialport/pmc960_upload.h"
#include "serialport/sc750_download.h"

#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <functional>

using namespace serialport;

namespace {
constexpr int kTimeoutMs = 20000;
constexpr qint64 kStopWithinMs = 50;

QString bds5Program() {
    QStringList lines{QStringLiteral("10$")};
    for (int i = 1; i <= 40; ++i) lines << QStringLiteral("P \"LINE %1\"").arg(i);
    lines << QStringLiteral("B");
    return lines.join(QLatin1Char('\n'));
}

std::vector<std::uint8_t> sc750Bin() {
    QStringList lines{QStringLiteral("DIM COUNT AS INTEGER")};
    for (int i = 1; i <= 60; ++i) lines << QStringLiteral("PRINT \"STEP %1 OF A LONG PROGRAM\"").arg(i);
    lines << QStringLiteral("END");
    const auto result = drive_core::sc750::compile(lines.join(QLatin1Char('\n')).toStdString() + "\n");
    if (!result.ok()) qFatal("test program does not compile");
    return result.bin;
}

// The user's stop, from the event loop, while the bytes just written are in flight: their answer is held
// until the stop has been requested.
void stopWhileInFlight(InProcessDriveLink& link, std::function<void()> stop) {
    link.holdAnswers = true;
    QTimer::singleShot(0, &link, [&link, stop = std::move(stop)] {
        stop();
        link.holdAnswers = false;
    });
}

// The stop request's write: one write, made while the request ran, holding `stop`.
void checkStopWrite(const InProcessDriveLink& link, qsizetype writesBefore, qint64 requestedAtMs,
                    const QByteArray& stop) {
    QVERIFY2(link.writes().size() > writesBefore, "the stop request wrote nothing");
    const auto& first = link.writes().at(writesBefore);
    QCOMPARE(first.bytes.left(stop.size()), stop);
    const qint64 delayMs = first.driveMs - requestedAtMs;
    QVERIFY2(delayMs >= 0 && delayMs <= kStopWithinMs, qPrintable(QString::number(delayMs)));
    qInfo("%s reached the link %lld ms of drive time after the request", stop.toHex().constData(),
          static_cast<long long>(delayMs));
}
} // namespace

class StopDuringTransferTest : public QObject {
    Q_OBJECT
private slots:
    // ^X (Stop Motion) while Bds5Download sends lines: the jog stops, the load ends with Esc, cancelled.
    void bds5CtrlXStopsMotionAndTheDownload() {
        InProcessDriveLink link(drive_core::DriveFamily::Bds5, 9600);
        Bds5Session session(link);
        link.open();
        QTRY_VERIFY_WITH_TIMEOUT(session.state() == Bds5Session::State::Ready, kTimeoutMs);
        QList<Bds5Response> answers;
        connect(&session, &Bds5Session::finished, this,
                [&answers](quint64, const Bds5Response& r) { answers.append(r); });
        for (const char* line : {"PLIM OFF", "EN", "J 500", "P VCMD"}) session.send(QString::fromLatin1(line));
        QTRY_COMPARE_WITH_TIMEOUT(answers.size(), 4, kTimeoutMs);
        for (const auto& r : answers) QVERIFY2(r.errors.isEmpty(), qPrintable(r.command));
        QCOMPARE(answers.last().lines.value(0).trimmed(), QStringLiteral("500"));

        Bds5Download download(session, bds5Program(), {});
        QSignalSpy finished(&download, &Bds5Transfer::finished);
        qsizetype stopWrite = -1;
        link.afterWrite = [&](const QByteArray& bytes) { // drive line 11 is on its way: ^X now
            if (bytes != "P \"LINE 10\"\r") return;
            stopWhileInFlight(link, [&] {
                stopWrite = link.writes().size();
                const qint64 requestedAt = link.driveMs();
                session.sendUrgent("\x18");
                checkStopWrite(link, stopWrite, requestedAt, "\x18");
            });
        };
        download.start();
        QVERIFY(finished.wait(kTimeoutMs));
        QVERIFY(stopWrite >= 0);
        const auto result = finished.first().at(0).value<Bds5TransferResult>();
        QCOMPARE(result.status, Bds5TransferResult::Status::Cancelled);
        QVERIFY2(result.summary.startsWith(QLatin1String("Stopped (^X)")), qPrintable(result.summary));
        QVERIFY2(result.summary.contains(QLatin1String("first 11 line")), qPrintable(result.summary));
        // Only the Esc that leaves program-load mode followed the ^X: no program line.
        QCOMPARE(link.writtenFrom(stopWrite), QByteArray("\x18\x1b"));

        // The jog decelerates at AMAX once the ^X reached the drive: no reading taken more than 50 ms of drive
        // time later shows motion (each query is answered as the drive reads it: its write time is the
        // reading's), and the readings fall to 0.
        const qint64 stoppedAt = link.writes().at(stopWrite).driveMs;
        QList<QPair<qint64, int>> readings; // drive ms after the ^X, VCMD
        while (readings.size() < 200 && (readings.isEmpty() || readings.last().second != 0)) {
            answers.clear();
            session.send(QStringLiteral("P VCMD"));
            QTRY_COMPARE_WITH_TIMEOUT(answers.size(), 1, kTimeoutMs);
            readings.append({link.writes().last().driveMs - stoppedAt, answers.first().lines.value(0).toInt()});
        }
        QCOMPARE(readings.last().second, 0);
        for (qsizetype i = 0; i < readings.size(); ++i) {
            QVERIFY(readings[i].second <= 500 && (i == 0 || readings[i].second <= readings[i - 1].second));
            if (readings[i].first > kStopWithinMs) QCOMPARE(readings[i].second, 0);
        }
        const qint64 lastMoving = readings.size() > 1 ? readings[readings.size() - 2].first : 0;
        qInfo("VCMD 0 between %lld and %lld ms of drive time after the ^X", static_cast<long long>(lastMoving),
              static_cast<long long>(readings.last().first));
        QCOMPARE(session.mode(), Bds5Mode::Interactive);
    }

    // Ctrl C (Stop Program) while W frames go out: no frame after it, the drive answers H, no program loaded.
    void sc750CtrlCStopsTheBinDownload() {
        InProcessDriveLink link(drive_core::DriveFamily::Sc750, 9600);
        Sc750Session session(link);
        link.open();
        QSignalSpy stopped(&session, &Sc750Session::programStopped);
        const auto bin = sc750Bin();
        QVERIFY2(bin.size() > 512, qPrintable(QString::number(bin.size())));
        Sc750Download download(session, bin);
        QSignalSpy finished(&download, &Sc750Download::finished);
        qsizetype stopWrite = -1;
        int frames = 0;
        link.afterWrite = [&](const QByteArray& bytes) { // the third W frame is on its way: Ctrl C now
            if (!bytes.startsWith("\x01W") || ++frames != 3) return;
            stopWhileInFlight(link, [&] {
                stopWrite = link.writes().size();
                const qint64 requestedAt = link.driveMs();
                session.sendStop();
                checkStopWrite(link, stopWrite, requestedAt, "\x03");
            });
        };
        download.start();
        QVERIFY(finished.wait(kTimeoutMs));
        QVERIFY(stopWrite >= 0);
        QCOMPARE(finished.first().at(0).toBool(), false);
        const QString why = finished.first().at(1).toString();
        QVERIFY2(why.startsWith(QLatin1String("stopped (Ctrl C) at byte 192 of")) &&
                     why.contains(QLatin1String("old program")),
                 qPrintable(why));
        QCOMPARE(link.writtenFrom(stopWrite), QByteArray("\x03")); // no W or Z frame followed
        QTRY_COMPARE_WITH_TIMEOUT(stopped.size(), 1, kTimeoutMs);  // the drive heard it

        QSignalSpy refused(&session, &Sc750Session::failed);
        session.send('R');
        QVERIFY(refused.wait(kTimeoutMs));
        QCOMPARE(refused.first().at(1).toString(), QStringLiteral("02 NO PROGRAM"));
    }

    // ESC (Stop) while lines go into the P editor: out of the editor at once, the buffer holds the lines sent.
    void pmc960EscStopsTheDownload() {
        InProcessDriveLink link(drive_core::DriveFamily::Pmc960, 9600);
        Pmc960Session session(link);
        link.open();
        QTRY_VERIFY_WITH_TIMEOUT(session.state() == Pmc960Session::State::Ready, kTimeoutMs);
        QStringList program{QStringLiteral("@A")};
        for (int i = 1; i <= 30; ++i) program << QStringLiteral("A%1").arg(i * 100);
        program << QStringLiteral("E");
        Pmc960Download download(session, program.join(QLatin1Char('\n')));
        QSignalSpy done(&download, &Pmc960Download::done);
        qsizetype stopWrite = -1;
        link.afterWrite = [&](const QByteArray& bytes) { // line 7 is on its way into the editor: ESC now
            if (bytes != "A600\r") return;
            stopWhileInFlight(link, [&] {
                stopWrite = link.writes().size();
                const qint64 requestedAt = link.driveMs();
                download.cancel();
                checkStopWrite(link, stopWrite, requestedAt, "\x1b");
            });
        };
        download.start();
        QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, kTimeoutMs);
        QVERIFY(stopWrite >= 0);
        const auto result = done.first().at(0).value<Pmc960DownloadResult>();
        QVERIFY(!result.ok);
        QVERIFY(result.cancelled);
        QVERIFY2(result.reason.contains(QLatin1String("cancelled (ESC) with 7 of 32 lines sent")),
                 qPrintable(result.reason));
        // After the ESC: CRs asking for the prompt and SW0, no program line.
        QTRY_VERIFY_WITH_TIMEOUT(session.state() == Pmc960Session::State::Ready, kTimeoutMs);
        QByteArray after = link.writtenFrom(stopWrite);
        QVERIFY2(after.startsWith("\x1b\r") && after.contains("SW0\r"), after.toHex().constData());
        after.replace("SW0\r", "");
        for (const char c : after) QVERIFY2(c == '\x1b' || c == '\r' || c == '\x1d' || c == '=', after.constData());

        Pmc960Upload upload(session);
        QSignalSpy uploaded(&upload, &Pmc960Upload::done);
        upload.start();
        QVERIFY(uploaded.wait(kTimeoutMs));
        QVERIFY2(uploaded.first().at(0).toBool(), qPrintable(uploaded.first().at(2).toString()));
        QCOMPARE(uploaded.first().at(1).toStringList(), program.mid(0, 7));
    }
};

QTEST_GUILESS_MAIN(StopDuringTransferTest)
#include "stop_during_transfer_test.moc"
