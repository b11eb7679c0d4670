// The PMC-960's one-character receive buffer over SimulatorLink (Options::overrunModel): bytes written back
// to back without flow control are lost as the manual warns (L2560-2568), while Pmc960Session over a link
// whose UART honours CTS loses none — the controller's communications checksum (<attn>h) proves it.
#include "serialport/pmc960_session.h"
#include "serialport/simulator_link.h"

#include <QSignalSpy>
#include <QTest>

using namespace serialport;

namespace {

SimulatorLink::Options overrunOptions(bool flowControl) {
    SimulatorLink::Options options{1.0, 9600, false};
    options.overrunModel = true;
    options.hardwareFlowControl = flowControl;
    return options;
}

int byteSum(const QByteArray& bytes) {
    int sum = 0;
    for (const char c : bytes) sum += static_cast<unsigned char>(c);
    return sum & 0xFFFF;
}

} // namespace

class Pmc960OverrunTest : public QObject {
    Q_OBJECT

private slots:
    void rawWritesWithoutFlowControlLoseBytes() {
        SimulatorLink link{drive_core::DriveFamily::Pmc960, overrunOptions(false)};
        QByteArray got;
        connect(&link, &Link::bytesReceived, this, [&got](const QByteArray& bytes) { got += bytes; });
        link.open();
        QTRY_VERIFY_WITH_TIMEOUT(got.endsWith("=}"), 30000);
        got.clear();
        link.write("SM2\r");
        QTRY_VERIFY_WITH_TIMEOUT(got.endsWith("=}"), 30000);
        got.clear();
        link.write("\x1dh"); // reads and resets the controller's checksum
        QTRY_VERIFY_WITH_TIMEOUT(got.endsWith('\r'), 30000);
        got.clear();
        // ';' lands while the controller is busy after the '+' trigger; the CR lands on it: ';' is lost,
        // so no } handshake comes, and the controller never counted it.
        link.write("J100+;\r");
        QTRY_VERIFY_WITH_TIMEOUT(got.endsWith("=}"), 30000);
        QCOMPARE(got, QByteArray("J100+\r\n=}"));
        got.clear();
        link.write("\x1dh");
        QTRY_VERIFY_WITH_TIMEOUT(got.endsWith('\r'), 30000);
        QCOMPARE(got.trimmed().toInt(), byteSum("J100+\r"));
    }

    void sessionWithFlowControlLosesNothing() {
        SimulatorLink link{drive_core::DriveFamily::Pmc960, overrunOptions(true)};
        Pmc960Session session{link};
        link.open();
        QSignalSpy finished(&session, &Pmc960Session::finished);
        QSignalSpy polled(&session, &Pmc960Session::pollAnswered);
        auto run = [&](const QByteArray& command) {
            const int before = int(finished.count());
            session.send(command);
            if (!QTest::qWaitFor([&] { return finished.count() > before; }, 5000)) return Pmc960Response{};
            return finished.last().at(1).value<Pmc960Response>();
        };
        QCOMPARE(run("SM2\r").error, 0);
        session.poll('h');
        QVERIFY(polled.wait(30000));
        session.resetChecksum();
        const Pmc960Response jog = run("J100+;\r");
        QCOMPARE(jog.error, 0);
        QVERIFY2(jog.text.contains('}'), jog.text.constData()); // the ';' arrived: at speed, the handshake
        QCOMPARE(run("J?").value, QStringLiteral("100"));
        QCOMPARE(run("J*\r").error, 0);
        session.poll('h');
        QVERIFY(polled.wait(30000));
        QCOMPARE(polled.last().at(2).toString().toInt(), int(session.sentChecksum()));
        QVERIFY(session.sentChecksum() != 0);
    }
};

QTEST_GUILESS_MAIN(Pmc960OverrunTest)
#include "pmc960_overrun_test.moc"
