// Bds5Session over the real QSerialPort path: a servodesk-sim --pty child process serves a simulated
// BDS5 on a pseudo-terminal, exactly as a USB serial adapter would serve a real one.
#include "serialport/bds5_session.h"
#include "serialport/serial_port_link.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTest>

using namespace serialport;

class PtySessionTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_sim.setProgram(QStringLiteral(SERVODESK_SIM));
        m_sim.setArguments({QStringLiteral("--drive"), QStringLiteral("bds5"), QStringLiteral("--pty")});
        m_sim.start();
        QVERIFY(m_sim.waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(m_sim.canReadLine(), 30000);
        const QString first = QString::fromLatin1(m_sim.readLine()).trimmed();
        QVERIFY2(first.startsWith(QStringLiteral("PTY /dev/")), qPrintable(first));
        m_path = first.mid(4);
    }

    void cleanup() {
        m_sim.terminate();
        QVERIFY(m_sim.waitForFinished(5000));
        QCOMPARE(m_sim.exitCode(), 0);
    }

    void helloWorldOverThePty() {
        SerialPortLink link(m_path, 9600);
        Bds5Session session(link);
        QByteArray raw;
        connect(&session, &Bds5Session::rawReceived, this, [&raw](const QByteArray& b) { raw += b; });
        link.open();
        QVERIFY(link.isOpen());
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Bds5Session::State::Ready, 30000);
        QCOMPARE(session.mode(), Bds5Mode::Interactive);

        QSignalSpy finished(&session, &Bds5Session::finished);
        session.send(QStringLiteral("P \"HELLO, WORLD\""));
        QVERIFY(finished.wait(30000));
        const auto response = finished.first().at(1).value<Bds5Response>();
        QCOMPARE(response.lines, QStringList{QStringLiteral("HELLO, WORLD")});
        QVERIFY(raw.contains("P \"HELLO, WORLD\"\r\nHELLO, WORLD\r\n-->"));
    }

    void variablesPersistAcrossReconnects() {
        {
            SerialPortLink link(m_path, 9600);
            Bds5Session session(link);
            link.open();
            QSignalSpy finished(&session, &Bds5Session::finished);
            session.send(QStringLiteral("X7=4242"));
            QVERIFY(finished.wait(30000));
            link.close();
        }
        SerialPortLink link(m_path, 9600);
        Bds5Session session(link);
        link.open();
        QSignalSpy finished(&session, &Bds5Session::finished);
        session.send(QStringLiteral("P X7"));
        QVERIFY(finished.wait(30000));
        QCOMPARE(finished.first().at(1).value<Bds5Response>().lines, QStringList{QStringLiteral("        4242")});
    }

    void openingAMissingPortReportsWhy() {
        SerialPortLink link(QStringLiteral("/dev/pts/does-not-exist"), 9600);
        QSignalSpy errors(&link, &Link::errorOccurred);
        link.open();
        QVERIFY(!link.isOpen());
        QCOMPARE(errors.count(), 1);
        QVERIFY(errors.first().first().toString().contains(QStringLiteral("does-not-exist")));
    }

private:
    QProcess m_sim;
    QString m_path;
};

QTEST_GUILESS_MAIN(PtySessionTest)
#include "pty_session_test.moc"
