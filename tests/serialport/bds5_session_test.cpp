// Bds5Session over SimulatorLink: commands go out only at a prompt, responses come back typed.
#include "serialport/bds5_session.h"
#include "serialport/simulator_link.h"

#include <QSignalSpy>
#include <QTest>

using namespace serialport;

class Bds5SessionTest : public QObject {
    Q_OBJECT

private:
    struct Fixture {
        SimulatorLink link{drive_core::DriveFamily::Bds5, SimulatorLink::Options{1.0, 9600}};
        Bds5Session session{link};
        QByteArray raw;
        Fixture() {
            QObject::connect(&session, &Bds5Session::rawReceived, [this](const QByteArray& b) { raw += b; });
            link.open();
        }
    };

    static Bds5Response run(Bds5Session& session, const QString& line) {
        QSignalSpy finished(&session, &Bds5Session::finished);
        const quint64 id = session.send(line);
        if (!finished.wait(30000)) {
            qWarning("no answer to %s", qPrintable(line));
            return {};
        }
        const auto args = finished.takeFirst();
        if (args.at(0).value<quint64>() != id) qWarning("answer for another command");
        return args.at(1).value<Bds5Response>();
    }

private slots:
    void becomesReadyAtTheSignOnPrompt() {
        Fixture f;
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Bds5Session::State::Ready, 30000);
        QCOMPARE(f.session.mode(), Bds5Mode::Interactive);
        QCOMPARE(f.session.lastPrompt(), QStringLiteral("-->"));
        QVERIFY(f.raw.contains("BDS5"));
    }

    void printReturnsTheLine() {
        Fixture f;
        const Bds5Response r = run(f.session, QStringLiteral("P \"HELLO, WORLD\""));
        QCOMPARE(r.lines, QStringList{QStringLiteral("HELLO, WORLD")});
        QVERIFY(r.errors.isEmpty());
        QCOMPARE(r.prompt, QStringLiteral("-->"));
    }

    void queuedCommandsRunInOrderEachAtItsPrompt() {
        Fixture f;
        QSignalSpy finished(&f.session, &Bds5Session::finished);
        f.session.send(QStringLiteral("X1=1000"));
        f.session.send(QStringLiteral("X2=X1*3"));
        f.session.send(QStringLiteral("P X1 X2"));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 30000);
        const auto last = finished.at(2).at(1).value<Bds5Response>();
        QCOMPARE(last.lines, QStringList{QStringLiteral("        1000        3000")});
        // The wire shows each command sent only after the previous prompt.
        QVERIFY(f.raw.contains("X1=1000\r\n-->X2=X1*3\r\n-->P X1 X2\r\n"));
    }

    void driveErrorsAreTyped() {
        Fixture f;
        const Bds5Response r = run(f.session, QStringLiteral("P 1/0"));
        QCOMPARE(r.errors.size(), 1);
        QCOMPARE(r.errors.first().code, 92);
        QCOMPARE(r.errors.first().entry, QStringLiteral("1/0"));
        QCOMPARE(r.errors.first().message, QStringLiteral("ZERO DIVIDE"));
        QVERIFY(r.lines.isEmpty());
    }

    void terminalBytesPassThroughAndTheDriveEchoes() {
        Fixture f;
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Bds5Session::State::Ready, 30000);
        f.raw.clear();
        f.session.sendRaw("P 6*7\r");
        QTRY_VERIFY_WITH_TIMEOUT(f.raw.endsWith("-->"), 30000);
        QCOMPARE(f.raw, QByteArray("P 6*7\r\n          42\r\n-->"));
    }

    void runModeShowsWhenNoPromptComes() {
        Fixture f;
        QSignalSpy finished(&f.session, &Bds5Session::finished);
        for (const char* line : {">BDS", "1$", "D 100000", "\x1b"}) f.session.sendRaw(QByteArray(line) + (line[0] == '\x1b' ? "" : "\r"));
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Bds5Session::State::Ready, 30000);
        f.session.sendRaw("RUN 1\r");
        QTRY_COMPARE_WITH_TIMEOUT(f.session.mode(), Bds5Mode::Running, 30000);
        f.raw.clear();
        f.session.sendRaw("\x1b"); // Esc: monitor mode
        QTRY_COMPARE_WITH_TIMEOUT(f.session.mode(), Bds5Mode::Monitor, 30000);
        QVERIFY(f.raw.contains("ENTER MONITOR MODE. PUSH ESCAPE TO EXIT"));
    }

    // A multidrop address puts the drive to sleep at once, with no prompt, until a backslash and its ID wake it
    // (L5449-5451): the ADDR command is done at its echo, the next command waits (nothing goes out to a
    // sleeping drive), and the wake-up's prompt lets it go.
    void aMultidropAddressSleepsUntilTheWakeUp() {
        Fixture f;
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Bds5Session::State::Ready, 30000);
        QSignalSpy sent(&f.session, &Bds5Session::rawSent);
        const Bds5Response r = run(f.session, QStringLiteral("ADDR 66"));
        QVERIFY(r.errors.isEmpty());
        QCOMPARE(f.session.mode(), Bds5Mode::Asleep);
        QCOMPARE(f.session.state(), Bds5Session::State::WaitingForPrompt);
        QSignalSpy finished(&f.session, &Bds5Session::finished);
        f.session.send(QStringLiteral("P 6*7"));
        f.session.sendRaw("\\B");
        QVERIFY2(finished.wait(30000), f.raw.right(60).toPercentEncoding().constData());
        QCOMPARE(finished.first().at(1).value<Bds5Response>().lines, QStringList{QStringLiteral("          42")});
        QCOMPARE(f.session.lastPrompt(), QStringLiteral("B->"));
        QByteArray wire;
        for (const auto& bytes : sent) wire += bytes.at(0).toByteArray();
        QCOMPARE(wire, QByteArray("ADDR 66\r\\BP 6*7\r"));
    }

    void closingTheLinkFailsTheCommandInFlight() {
        Fixture f;
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Bds5Session::State::Ready, 30000);
        QSignalSpy failed(&f.session, &Bds5Session::failed);
        f.session.send(QStringLiteral("P 1"));
        f.session.send(QStringLiteral("P 2"));
        f.link.close();
        QCOMPARE(failed.count(), 2);
        QCOMPARE(f.session.state(), Bds5Session::State::Closed);
    }
};

QTEST_GUILESS_MAIN(Bds5SessionTest)
#include "bds5_session_test.moc"
