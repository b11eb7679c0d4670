// Sc750Session and Sc750Download over SimulatorLink: compile a manual example, download it with progress,
// run it, see its PRINT output, hit a breakpoint, read and write a variable, continue, stop with Ctrl C.
#include "drive_core/sc750/sc750_compiler.h"
#include "serialport/sc750_download.h"
#include "serialport/sc750_session.h"
#include "serialport/simulator_link.h"

#include <QSignalSpy>
#include <QTest>

#include <fstream>
#include <sstream>

using namespace serialport;

class Sc750SessionTest : public QObject {
    Q_OBJECT

private:
    struct Fixture {
        SimulatorLink link{drive_core::DriveFamily::Sc750, SimulatorLink::Options{1.0, 9600, false}};
        Sc750Session session{link};
        QByteArray output;
        Fixture() {
            QObject::connect(&session, &Sc750Session::programOutput, [this](const QByteArray& b) { output += b; });
            link.open();
        }
    };

    static Sc750Reply ask(Sc750Session& session, char letter, const QString& payload = {}) {
        QSignalSpy finished(&session, &Sc750Session::finished);
        QSignalSpy failed(&session, &Sc750Session::failed);
        const quint64 id = session.send(letter, payload);
        if (!QTest::qWaitFor([&] { return finished.count() + failed.count() > 0; }, 5000)) return {};
        if (!failed.isEmpty()) return Sc750Reply{'!', failed.first().at(1).toString()};
        if (finished.first().at(0).value<quint64>() != id) qWarning("answer for another command");
        return finished.first().at(1).value<Sc750Reply>();
    }

    static std::vector<std::uint8_t> partNumberBin() {
        std::ifstream in(SC750_EXAMPLES_DIR "/repaired/04-part-num.bas", std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        const auto result = drive_core::sc750::compile(s.str());
        if (!result.ok()) qWarning("%s", result.error->text().c_str());
        return result.bin;
    }

private slots:
    void identifiesTheController() {
        Fixture f;
        QTRY_VERIFY_WITH_TIMEOUT(f.link.isOpen(), 30000);
        const Sc750Reply r = ask(f.session, 'V');
        QCOMPARE(r.letter, 'V');
        QCOMPARE(r.payload, QStringLiteral("752,2.8,1,255"));
    }

    void downloadRunBreakpointVariable() {
        Fixture f;
        QTRY_VERIFY_WITH_TIMEOUT(f.link.isOpen(), 30000);
        const auto bin = partNumberBin();
        QVERIFY(!bin.empty());
        Sc750Download download(f.session, bin);
        QSignalSpy progress(&download, &Sc750Download::progress);
        QSignalSpy done(&download, &Sc750Download::finished);
        download.start();
        QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 30000);
        QVERIFY2(done.first().at(0).toBool(), qPrintable(done.first().at(1).toString()));
        QVERIFY(progress.count() > 10);
        QCOMPARE(progress.last().at(0).toLongLong(), qint64(bin.size()));

        // line 76 is INPUT "PART NUMBER"; STR1$
        QCOMPARE(ask(f.session, 'B', QStringLiteral("+76")).payload, QStringLiteral("76"));
        QSignalSpy hit(&f.session, &Sc750Session::breakpointHit);
        QCOMPARE(ask(f.session, 'R').letter, 'R');
        QTRY_COMPARE_WITH_TIMEOUT(hit.count(), 1, 30000);
        QCOMPARE(hit.first().at(0).toInt(), 76);
        QVERIFY(f.output.contains("ENTER PART NUMBER:"));
        QCOMPARE(ask(f.session, 'G', QStringLiteral("PITCH")).payload, QStringLiteral("PITCH=.5"));
        QCOMPARE(ask(f.session, 'G', QStringLiteral("ACCEL$(2)")).payload, QStringLiteral("ACCEL$(2)=\"10000\""));
        QCOMPARE(ask(f.session, 'P', QStringLiteral("PITCH=0.25")).payload, QStringLiteral("PITCH=.25"));
        QCOMPARE(ask(f.session, '?').payload.left(5), QStringLiteral("B,76,"));

        QCOMPARE(ask(f.session, 'C').letter, 'C');
        QTRY_VERIFY_WITH_TIMEOUT(f.output.contains("PART NUMBER? "), 30000);
        QSignalSpy stopped(&f.session, &Sc750Session::programStopped);
        f.session.sendStop();
        QTRY_COMPARE_WITH_TIMEOUT(stopped.count(), 1, 30000);
        QCOMPARE(ask(f.session, '?').payload.left(1), QStringLiteral("S"));
    }

    void programEventsArriveAsSignals() {
        Fixture f;
        QTRY_VERIFY_WITH_TIMEOUT(f.link.isOpen(), 30000);
        const auto program = drive_core::sc750::compile("DIM a(2) AS INTEGER\nPRINT \"go\"\na(3) = 1\n");
        QVERIFY(program.ok());
        Sc750Download download(f.session, program.bin);
        QSignalSpy done(&download, &Sc750Download::finished);
        download.start();
        QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 10000);
        QSignalSpy error(&f.session, &Sc750Session::runTimeError);
        QCOMPARE(ask(f.session, 'R').letter, 'R');
        QTRY_COMPARE_WITH_TIMEOUT(error.count(), 1, 30000);
        QCOMPARE(error.first().at(0).toInt(), 244); // F 4
        QCOMPARE(error.first().at(1).toInt(), 3);
        QVERIFY(error.first().at(2).toString().contains(QLatin1String("SUBSCRIPT OUT OF RANGE")));
        QCOMPARE(f.output, QByteArray("go\r\n"));
        QCOMPARE(ask(f.session, 'G', QStringLiteral("FAULTCODE")).payload, QStringLiteral("FAULTCODE=244"));

        const auto ending = drive_core::sc750::compile("PRINT \"bye\"\nEND\n");
        Sc750Download second(f.session, ending.bin);
        QSignalSpy secondDone(&second, &Sc750Download::finished);
        second.start();
        QTRY_COMPARE_WITH_TIMEOUT(secondDone.count(), 1, 10000);
        QVERIFY(secondDone.first().at(0).toBool());
        QSignalSpy ended(&f.session, &Sc750Session::programEnded);
        QCOMPARE(ask(f.session, 'R').letter, 'R');
        QTRY_COMPARE_WITH_TIMEOUT(ended.count(), 1, 30000);
        QCOMPARE(ended.first().at(0).toInt(), 2);
    }

    void aDrivesErrorReplyArrivesAsFailed() {
        Fixture f;
        QTRY_VERIFY_WITH_TIMEOUT(f.link.isOpen(), 30000);
        const Sc750Reply r = ask(f.session, 'R');
        QCOMPARE(r.letter, '!');
        QCOMPARE(r.payload, QStringLiteral("02 NO PROGRAM"));
    }

    void cancelStopsTheDownloadAndKeepsTheOldProgram() {
        Fixture f;
        QTRY_VERIFY_WITH_TIMEOUT(f.link.isOpen(), 30000);
        Sc750Download download(f.session, partNumberBin());
        QSignalSpy done(&download, &Sc750Download::finished);
        connect(&download, &Sc750Download::progress, &download, [&download](qint64 sent, qint64) {
            if (sent >= 640) download.cancel();
        });
        download.start();
        QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 30000);
        QCOMPARE(done.first().at(0).toBool(), false);
        const QString why = done.first().at(1).toString();
        QVERIFY2(why.startsWith(QLatin1String("cancelled at byte ")) &&
                     why.endsWith(QLatin1String("keeps its old program")),
                 qPrintable(why));
        QCOMPARE(ask(f.session, '?').payload.left(1), QStringLiteral("N"));
    }
};

QTEST_GUILESS_MAIN(Sc750SessionTest)
#include "sc750_session_test.moc"
