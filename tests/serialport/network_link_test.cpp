// NetworkLink (issue 21): the IDE's and the CLI's link to a serial device server. A BDS5 session over
// rfc2217:// and tcp:// to servodesk-sim --tcp (a child process, as a device server on the loopback); a server
// that refuses RFC 2217 and one that goes away are said, never taken for a drive; and the Telnet framing
// (IAC doubled, each option answered once, the com-port answers) against RFC 854 and RFC 2217's own bytes.
#include "serialport/bds5_session.h"
#include "serialport/network_link.h"
#include "serialport/rfc2217.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

using namespace serialport;

namespace {
constexpr int kTimeoutMs = 30000;
std::string s(std::initializer_list<int> bytes) {
    std::string out;
    for (const int b : bytes) out += char(b);
    return out;
}
} // namespace

class NetworkLinkTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        m_sim.setProgram(QStringLiteral(SERVODESK_SIM));
        m_sim.setArguments({QStringLiteral("--drive"), QStringLiteral("bds5"), QStringLiteral("--tcp"), QStringLiteral("0")});
        m_sim.start();
        QVERIFY(m_sim.waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(m_sim.canReadLine(), kTimeoutMs);
        const QString first = QString::fromLatin1(m_sim.readLine()).trimmed();
        QVERIFY2(first.startsWith(QStringLiteral("TCP 127.0.0.1:")), qPrintable(first));
        m_port = quint16(first.section(QLatin1Char(':'), -1).toUInt());
    }

    void cleanup() {
        m_sim.terminate();
        m_sim.waitForFinished(5000);
    }

    void aSessionOverEitherProtocol_data() {
        QTest::addColumn<QString>("scheme");
        QTest::addColumn<QString>("description");
        QTest::newRow("RFC 2217") << QStringLiteral("rfc2217") << QStringLiteral("rfc2217://127.0.0.1:%1 9600 8N1");
        QTest::newRow("raw TCP") << QStringLiteral("tcp") << QStringLiteral("tcp://127.0.0.1:%1");
    }
    void aSessionOverEitherProtocol() {
        QFETCH(QString, scheme);
        QFETCH(QString, description);
        const auto address = NetworkLink::parse(QStringLiteral("%1://127.0.0.1:%2").arg(scheme).arg(m_port));
        QVERIFY(address);
        NetworkLink link(*address, 9600);
        QCOMPARE(link.description(), description.arg(m_port));
        Bds5Session session(link);
        QSignalSpy opened(&link, &Link::opened);
        link.open();
        QVERIFY(opened.wait(kTimeoutMs)); // RFC 2217: only once the server took 9600 8N1
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Bds5Session::State::Ready, kTimeoutMs);
        QSignalSpy finished(&session, &Bds5Session::finished);
        session.send(QStringLiteral("P \"HELLO, WORLD\""));
        QVERIFY(finished.wait(kTimeoutMs));
        QCOMPARE(finished.first().at(1).value<Bds5Response>().lines, QStringList{QStringLiteral("HELLO, WORLD")});
    }

    void theServerGoingAwayIsSaid() {
        NetworkLink link(*NetworkLink::parse(QStringLiteral("tcp://127.0.0.1:%1").arg(m_port)), 9600);
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy errors(&link, &Link::errorOccurred);
        QSignalSpy closed(&link, &Link::closed);
        link.open();
        QVERIFY(opened.wait(kTimeoutMs));
        m_sim.kill();
        QVERIFY(closed.wait(kTimeoutMs));
        QVERIFY(!link.isOpen());
        QCOMPARE(errors.count(), 1);
        QVERIFY2(errors.first().at(0).toString().contains(QStringLiteral("closed the connection")),
                 qPrintable(errors.first().at(0).toString()));
    }

    void aServerThatRefusesRfc2217IsNotTakenForADrive() {
        QTcpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost));
        connect(&server, &QTcpServer::newConnection, this, [&server] {
            QTcpSocket* client = server.nextPendingConnection();
            connect(client, &QTcpSocket::readyRead, client, [client] {
                client->readAll();
                client->write(QByteArray::fromStdString(rfc2217::option(rfc2217::kDont, rfc2217::kComPortOption)));
            });
        });
        NetworkLink link(*NetworkLink::parse(QStringLiteral("rfc2217://127.0.0.1:%1").arg(server.serverPort())), 9600);
        QSignalSpy opened(&link, &Link::opened);
        QSignalSpy errors(&link, &Link::errorOccurred);
        link.open();
        QVERIFY(errors.wait(kTimeoutMs));
        QVERIFY2(errors.first().at(0).toString().contains(QStringLiteral("does not do RFC 2217")),
                 qPrintable(errors.first().at(0).toString()));
        QCOMPARE(opened.count(), 0);
        QVERIFY(!link.isOpen());
    }

    void addresses() {
        const auto v6 = NetworkLink::parse(QStringLiteral("rfc2217://[::1]:7000"));
        QVERIFY(v6);
        QCOMPARE(v6->host, QStringLiteral("::1"));
        QCOMPARE(v6->port, quint16(7000));
        QCOMPARE(v6->protocol, NetworkLink::Protocol::Rfc2217);
        QCOMPARE(NetworkLink::parse(QStringLiteral("TCP://plant-gw:4001"))->protocol, NetworkLink::Protocol::Raw);
        QVERIFY(!NetworkLink::parse(QStringLiteral("/dev/ttyUSB0")));
        QVERIFY(NetworkLink::problem(QStringLiteral("/dev/ttyUSB0")).isEmpty()); // a port name, not a URL
        QVERIFY(!NetworkLink::problem(QStringLiteral("tcp://plant-gw")).isEmpty());
        QVERIFY(!NetworkLink::problem(QStringLiteral("rfc2217://plant-gw:70000")).isEmpty());
    }

    // RFC 854: a data byte 255 travels as IAC IAC; RFC 2217: SET-BAUDRATE is IAC SB 44 1 <4 bytes> IAC SE,
    // answered with command 101; an option already agreed is not answered again (no negotiation loop).
    void telnetFraming() {
        QCOMPARE(rfc2217::escape(s({'a', 255, 'b'})), s({'a', 255, 255, 'b'}));
        rfc2217::Decoder decoder;
        std::vector<rfc2217::Decoder::Command> commands;
        // Split across reads: data, a doubled IAC, WILL 44, and a subnegotiation with an IAC in its value.
        std::string data = decoder.feed(s({'x', 255}), commands);
        data += decoder.feed(s({255, 255, 251, 44, 255, 250, 44, 1, 0, 0, 255, 255}), commands);
        data += decoder.feed(s({0, 255, 240, 'y'}), commands);
        QCOMPARE(data, s({'x', 255, 'y'}));
        QCOMPARE(commands.size(), std::size_t(2));
        QCOMPARE(int(commands[0].verb), int(rfc2217::kWill));
        QCOMPARE(int(commands[0].option), 44);
        QCOMPARE(int(commands[1].verb), int(rfc2217::kSb));
        QCOMPARE(commands[1].value, s({1, 0, 0, 255, 0})); // SET-BAUDRATE 65280

        rfc2217::Server server;
        std::string reply;
        QCOMPARE(server.feed(s({255, 253, 44, 255, 253, 44, 255, 253, 1}), reply), std::string());
        QCOMPARE(reply, s({255, 251, 44, 255, 252, 1})); // WILL 44 once; WONT ECHO
        reply.clear();
        server.feed(rfc2217::subnegotiation(rfc2217::kSetBaudRate, rfc2217::u32(19200)), reply);
        QCOMPARE(reply, s({255, 250, 44, 101, 0, 0, 0x4b, 0x00, 255, 240}));
        QCOMPARE(server.baudRate(), 19200u);
        reply.clear();
        server.feed(rfc2217::subnegotiation(rfc2217::kSetBaudRate, rfc2217::u32(0)), reply); // a query
        QCOMPARE(reply, s({255, 250, 44, 101, 0, 0, 0x4b, 0x00, 255, 240}));
    }

private:
    QProcess m_sim;
    quint16 m_port = 0;
};

QTEST_MAIN(NetworkLinkTest)
#include "network_link_test.moc"
