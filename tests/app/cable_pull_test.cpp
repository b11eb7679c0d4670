// The cable pulled mid-download: servodesk-sim serves a BDS5 on a pty reached through a fixed symbolic
// link (--link), and is killed while a program is being sent at 9600 baud. The download fails with a
// reason, the connection says it is lost and keeps trying; when the simulator comes back on the same name
// the IDE's connection reopens by itself and the next download is verified.
#include "app/drive/drive_connection.h"

#include "serialport/bds5_download.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace serialport;
using Status = Bds5TransferResult::Status;

namespace {
QString longProgram() {
    QStringList lines{QStringLiteral("10$")};
    for (int i = 1; i <= 60; ++i) lines << QStringLiteral("P \"LINE %1 OF A LONG PROGRAM\"").arg(i);
    lines << QStringLiteral("B");
    return lines.join(QLatin1Char('\n'));
}
} // namespace

class CablePullTest : public QObject {
    Q_OBJECT

private:
    void startSimulator(QProcess& sim) {
        sim.setProgram(QStringLiteral(SERVODESK_SIM));
        sim.setArguments({QStringLiteral("--drive"), QStringLiteral("bds5"), QStringLiteral("--pty"),
                          QStringLiteral("--link"), m_linkPath});
        sim.start();
        QVERIFY(sim.waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 5000);
        const QString first = QString::fromLatin1(sim.readLine()).trimmed();
        QVERIFY2(first.startsWith(QStringLiteral("PTY /dev/")), qPrintable(first));
    }

    QTemporaryDir m_dir;
    QString m_linkPath;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_linkPath = m_dir.filePath(QStringLiteral("drive"));
    }

    void downloadFailsClearlyAndTheConnectionComesBack() {
        QProcess sim;
        startSimulator(sim);
        app::DriveConnection connection;
        QSignalSpy connected(&connection, &app::DriveConnection::connectedChanged);
        QSignalSpy errors(&connection, &app::DriveConnection::errorOccurred);
        connection.connectTo(app::ConnectionChoice::serialPort(m_linkPath, 9600));
        QTRY_VERIFY_WITH_TIMEOUT(connection.session() &&
                                     connection.session()->state() == Bds5Session::State::Ready,
                                 5000);

        auto download = std::make_unique<Bds5Download>(*connection.session(), longProgram(), Bds5Download::Options{});
        QSignalSpy progress(download.get(), &Bds5Transfer::progress);
        QSignalSpy finished(download.get(), &Bds5Transfer::finished);
        download->start();
        QTRY_VERIFY_WITH_TIMEOUT(!progress.isEmpty() && progress.last().at(0).toInt() >= 5, 10000);
        sim.kill(); // the cable is pulled
        QVERIFY(sim.waitForFinished(5000));

        QVERIFY(finished.wait(10000));
        const auto result = finished.first().at(0).value<Bds5TransferResult>();
        QCOMPARE(result.status, Status::Failed);
        QVERIFY2(!result.summary.isEmpty(), "a failed download says why");
        QTRY_VERIFY_WITH_TIMEOUT(connection.isReconnecting(), 5000);
        QVERIFY(!connection.isConnected());
        bool saidLost = false;
        for (const auto& e : errors) saidLost |= e.at(0).toString().contains(QLatin1String("lost"));
        QVERIFY2(saidLost, "the user is told the connection was lost");

        // The simulator is back under the same name: the connection reopens by itself.
        QProcess again;
        startSimulator(again);
        QTRY_VERIFY_WITH_TIMEOUT(connection.isConnected(), 5000);
        QVERIFY(!connection.isReconnecting());
        QTRY_VERIFY_WITH_TIMEOUT(connection.session()->state() == Bds5Session::State::Ready, 5000);

        Bds5Download retry(*connection.session(), QStringLiteral("10$\nP \"BACK\"\nB\n"), {});
        QSignalSpy retried(&retry, &Bds5Transfer::finished);
        retry.start();
        QVERIFY(retried.wait(15000));
        const auto ok = retried.first().at(0).value<Bds5TransferResult>();
        QVERIFY2(ok.ok(), qPrintable(ok.summary));
        again.terminate();
        QVERIFY(again.waitForFinished(5000));
    }

    void disconnectingStopsTheRetries() {
        QProcess sim;
        startSimulator(sim);
        app::DriveConnection connection;
        connection.connectTo(app::ConnectionChoice::serialPort(m_linkPath, 9600));
        QTRY_VERIFY_WITH_TIMEOUT(connection.isConnected(), 5000);
        sim.kill();
        QVERIFY(sim.waitForFinished(5000));
        QTRY_VERIFY_WITH_TIMEOUT(connection.isReconnecting(), 5000);
        connection.disconnectDrive();
        QVERIFY(!connection.isReconnecting());
    }
};

QTEST_GUILESS_MAIN(CablePullTest)
#include "cable_pull_test.moc"
