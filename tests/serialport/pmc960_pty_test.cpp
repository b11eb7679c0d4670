// The PMC-960 over the real QSerialPort path with its hardware flow control (seed-pmc960 §4.1): a
// servodesk-sim --drive pmc960 --pty child serves the controller on a pseudo-terminal; the link sets RTS/CTS
// on the port (read back with stty, as a user checking the port would) and Pmc960Session talks through it.
#include "serialport/pmc960_session.h"
#include "serialport/serial_port_link.h"

#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

using namespace serialport;

namespace {

// stty -a of the port: the terminal settings the kernel holds for it ("crtscts" or "-crtscts").
QStringList sttyFlags(const QString& path) {
    QProcess stty;
    stty.start(QStringLiteral("stty"), {QStringLiteral("-F"), path, QStringLiteral("-a")});
    if (!stty.waitForFinished(5000)) return {};
    return QString::fromLatin1(stty.readAllStandardOutput()).split(QRegularExpression(QStringLiteral("[\\s;]+")));
}

} // namespace

class Pmc960PtyTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_sim.setProgram(QStringLiteral(SERVODESK_SIM));
        m_sim.setArguments({QStringLiteral("--drive"), QStringLiteral("pmc960"), QStringLiteral("--pty")});
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
    }

    void hardwareFlowControlIsSetOnThePortAndTheControllerAnswers() {
        SerialPortLink link(m_path, 9600, SerialPortLink::FlowControl::Hardware);
        QVERIFY(link.description().endsWith(QStringLiteral("RTS/CTS")));
        Pmc960Session session(link);
        link.open();
        QVERIFY(link.isOpen());
        QVERIFY2(sttyFlags(m_path).contains(QStringLiteral("crtscts")), "RTS/CTS is not set on the port");
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 10000);

        QSignalSpy finished(&session, &Pmc960Session::finished);
        session.send("A3500\r");
        QVERIFY(finished.wait(30000));
        session.send("A?");
        QVERIFY(finished.wait(30000));
        const auto response = finished.last().at(1).value<Pmc960Response>();
        QCOMPARE(response.error, 0);
        QCOMPARE(response.value.trimmed(), QStringLiteral("3500"));
    }

    void threeWirePortsHaveNoFlowControl() {
        SerialPortLink link(m_path, 9600);
        link.open();
        QVERIFY(link.isOpen());
        QVERIFY(sttyFlags(m_path).contains(QStringLiteral("-crtscts")));
    }

private:
    QProcess m_sim;
    QString m_path;
};

QTEST_GUILESS_MAIN(Pmc960PtyTest)
#include "pmc960_pty_test.moc"
