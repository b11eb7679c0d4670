// Program and variable transfers over SimulatorLink, asserting what a user would see: the program runs and
// prints, uploads match, a changed drive fails verification, errors land on the right editor line, .VAR
// files survive a round trip, refusals (ERR 51, 86, 110) and cancels say what the drive holds, and a
// checksum lost on the line is never taken for a verified program.
#include "serialport/bds5_download.h"
#include "serialport/bds5_session.h"
#include "serialport/bds5_upload.h"
#include "serialport/bds5_variable_file.h"
#include "serialport/bds5_variables_from_drive.h"
#include "serialport/bds5_variables_to_drive.h"
#include "serialport/bds5_verify.h"
#include "serialport/simulator_link.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace serialport;
using Status = Bds5TransferResult::Status;

namespace {
const QString kHelloWorld = QStringLiteral("10$\nP \"HELLO WORLD\"\nB\n"); // L3427-3462

// Line noise on one request: the next `damaged` "P CHECKSUM" lines the IDE sends reach the drive as
// "P CHECKSUX" (one bit flipped in the M), which the drive refuses. Otherwise it passes the bytes as they are.
class ChecksumNoise final : public Link {
public:
    explicit ChecksumNoise(Link& inner) : m_inner(inner) {
        connect(&inner, &Link::bytesReceived, this, &Link::bytesReceived);
        connect(&inner, &Link::opened, this, &Link::opened);
        connect(&inner, &Link::closed, this, &Link::closed);
        connect(&inner, &Link::errorOccurred, this, &Link::errorOccurred);
    }
    void open() override { m_inner.open(); }
    void close() override { m_inner.close(); }
    bool isOpen() const override { return m_inner.isOpen(); }
    void write(const QByteArray& bytes) override {
        QByteArray b = bytes;
        if (damaged > 0 && b.contains("P CHECKSUM")) {
            b.replace("P CHECKSUM", "P CHECKSUX");
            --damaged;
        }
        m_inner.write(b);
    }
    QString description() const override { return m_inner.description(); }
    int baudRate() const override { return m_inner.baudRate(); }
    std::optional<double> driveClockMs() const override { return m_inner.driveClockMs(); }
    int damaged = 0;

private:
    Link& m_inner;
};

struct Fixture {
    SimulatorLink link;
    ChecksumNoise noise{link};
    Bds5Session session{noise};
    explicit Fixture(bool paced = false)
        : link(drive_core::DriveFamily::Bds5, SimulatorLink::Options{1.0, 9600, paced}) {
        noise.open();
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Bds5Session::State::Ready, 30000);
    }
    Bds5Response run(const QString& line) {
        QSignalSpy finished(&session, &Bds5Session::finished);
        const quint64 id = session.send(line);
        for (int i = 0; i < 200 && !(finished.count() && finished.last().at(0).value<quint64>() == id); ++i)
            finished.wait(50);
        return finished.isEmpty() ? Bds5Response{} : finished.last().at(1).value<Bds5Response>();
    }
    Bds5Response escape() {
        QSignalSpy finished(&session, &Bds5Session::finished);
        session.sendEscape();
        finished.wait(30000);
        return finished.isEmpty() ? Bds5Response{} : finished.last().at(1).value<Bds5Response>();
    }
};

Bds5TransferResult runTransfer(Bds5Transfer& transfer, int timeoutMs = 30000) {
    QSignalSpy finished(&transfer, &Bds5Transfer::finished);
    transfer.start();
    if (!finished.wait(timeoutMs)) return {Status::Failed, QStringLiteral("test: no result")};
    return finished.first().at(0).value<Bds5TransferResult>();
}

Bds5TransferResult download(Fixture& f, const QString& text, Bds5Download::Options options = {}) {
    Bds5Download d(f.session, text, options);
    return runTransfer(d);
}
} // namespace

class Bds5TransferTest : public QObject {
    Q_OBJECT

private slots:
    void helloWorldDownloadsVerifiesAndRuns() {
        Fixture f(true); // at 9600 baud, as a real drive
        const Bds5TransferResult r = download(f, kHelloWorld);
        QCOMPARE(r.status, Status::Ok);
        QVERIFY2(r.summary.contains(QStringLiteral("Verified")), qPrintable(r.summary));
        QVERIFY(r.checksum.has_value());
        QVERIFY2(r.summary.contains(QStringLiteral("P CHECKSUM = %1").arg(*r.checksum)),
                 qPrintable(r.summary));
        QCOMPARE(f.session.mode(), Bds5Mode::Interactive);
        const Bds5Response run = f.run(QStringLiteral("RUN 10"));
        QCOMPARE(run.lines, QStringList{QStringLiteral("HELLO WORLD")});
    }

    // A verify whose P CHECKSUM got no number has not confirmed the program (the request may have reached the
    // drive as a command that changed it, as in serialport.download_campaign): Failed, never Verified. The
    // download then reads back once more, and that verify's checksum confirms it.
    void aChecksumLostOnTheLineIsNotVerified() {
        Fixture f;
        QCOMPARE(download(f, kHelloWorld).status, Status::Ok);
        f.noise.damaged = 1;
        Bds5Verify verify(f.session, Bds5ProgramText::prepare(kHelloWorld, false));
        const Bds5TransferResult unconfirmed = runTransfer(verify);
        QCOMPARE(f.noise.damaged, 0);
        QCOMPARE(unconfirmed.status, Status::Failed);
        QVERIFY(!unconfirmed.checksum.has_value());
        QVERIFY2(unconfirmed.summary.contains(QStringLiteral("P CHECKSUM gave no number")) &&
                     unconfirmed.summary.contains(QStringLiteral("could not be confirmed")),
                 qPrintable(unconfirmed.summary));

        f.noise.damaged = 1;
        const Bds5TransferResult r = download(f, QStringLiteral("20$\nP \"AGAIN\"\nB\n"));
        QCOMPARE(f.noise.damaged, 0);
        QCOMPARE(r.status, Status::Ok);
        QVERIFY(r.checksum.has_value());
        QVERIFY2(r.summary.contains(QStringLiteral("Verified")) &&
                     r.summary.contains(QStringLiteral("P CHECKSUM = %1").arg(*r.checksum)),
                 qPrintable(r.summary));
        QCOMPARE(f.run(QStringLiteral("RUN 20")).lines, QStringList{QStringLiteral("AGAIN")});
    }

    void uploadReturnsTheSameText() {
        Fixture f;
        const QString text = QStringLiteral("; greeting\n10$\n\n  P \"HELLO WORLD\"  ; indented\nB\n");
        QCOMPARE(download(f, text).status, Status::Ok);
        Bds5Upload upload(f.session);
        QSignalSpy progress(&upload, &Bds5Transfer::progress);
        const Bds5TransferResult r = runTransfer(upload);
        QCOMPARE(r.status, Status::Ok);
        QCOMPARE(r.lines.join(QLatin1Char('\n')) + QLatin1Char('\n'), text); // blank line and comments kept
        QVERIFY(!progress.isEmpty());
        QCOMPARE(r.summary, QStringLiteral("Read 5 line(s) from the drive (<BDS)."));
    }

    void verifyFindsAProgramChangedBehindTheIdesBack() {
        Fixture f;
        QCOMPARE(download(f, kHelloWorld).status, Status::Ok);
        // Someone at the terminal reloads the program with one line changed: raw bytes, as typed.
        f.session.sendRaw(">BDS\r");
        QTRY_COMPARE_WITH_TIMEOUT(f.session.mode(), Bds5Mode::ProgramLoad, 30000);
        f.session.sendRaw("10$\r");
        f.session.sendRaw("P \"HELLO MARS\"\r");
        f.session.sendRaw("B\r");
        f.session.sendRaw("\x1b");
        QTRY_COMPARE_WITH_TIMEOUT(f.session.mode(), Bds5Mode::Interactive, 30000);
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Bds5Session::State::Ready, 30000);
        Bds5Verify verify(f.session, Bds5ProgramText::prepare(kHelloWorld, false));
        const Bds5TransferResult r = runTransfer(verify);
        QCOMPARE(r.status, Status::Mismatch);
        QCOMPARE(r.mismatchDriveLine, 2);
        QCOMPARE(r.mismatchSourceLine, 2);
        QCOMPARE(r.expected, QStringLiteral("P \"HELLO WORLD\""));
        QCOMPARE(r.actual, QStringLiteral("P \"HELLO MARS\""));
        QVERIFY2(r.summary.contains(QStringLiteral("drive line 2")), qPrintable(r.summary));
    }

    void strippedCommentsStillMapDriveErrorsToEditorLines() {
        Fixture f;
        const QString text = QStringLiteral("; a program with comments\n"
                                            "10$            ; the label\n"
                                            "P \"A;B\" ; quoted ; stays\n"
                                            "\n"
                                            "; about to fail\n"
                                            "D -1\n"
                                            "B\n");
        Bds5Download d(f.session, text, {QString(), true, true});
        const Bds5TransferResult r = runTransfer(d);
        QCOMPARE(r.status, Status::Ok);
        QCOMPARE(d.program().lines(), (QStringList{QStringLiteral("10$"), QStringLiteral("P \"A;B\""),
                                                   QStringLiteral("D -1"), QStringLiteral("B")}));
        QVERIFY2(r.summary.contains(QStringLiteral("3 comment or blank line(s) not sent")),
                 qPrintable(r.summary));
        const Bds5Response run = f.run(QStringLiteral("RUN 10"));
        QCOMPARE(run.lines, QStringList{QStringLiteral("A;B")});
        QCOMPARE(run.errors.size(), 1);
        QCOMPARE(run.errors.first().code, 83);
        QCOMPARE(run.errors.first().programLine, 3); // the drive counts only the lines it holds
        QCOMPARE(d.program().sourceLine(3), 6);      // ... which is editor line 6
    }

    void variablesRoundTripThroughAVarFile() {
        Fixture f;
        QVERIFY(f.run(QStringLiteral("X1=1234")).errors.isEmpty());
        QVERIFY(f.run(QStringLiteral("X250=-7")).errors.isEmpty());
        QVERIFY(f.run(QStringLiteral("KP=1234")).errors.isEmpty());
        Bds5VariablesFromDrive read(f.session);
        const Bds5TransferResult dumped = runTransfer(read);
        QCOMPARE(dumped.status, Status::Ok);
        QCOMPARE(read.variables().valueOf(QStringLiteral("X1")), QStringLiteral("1234"));
        QCOMPARE(read.variables().valueOf(QStringLiteral("KP")), QStringLiteral("1234"));
        QVERIFY(read.variables()
                    .valueOf(QStringLiteral("VMAX"))
                    .isEmpty()); // factory-protected: ";VMAX" in DUMP, not kept

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("SAVED.VAR"));
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(read.variables().toText({QStringLiteral("saved by the test")}).toLatin1());
        out.close();

        QVERIFY(f.run(QStringLiteral("X1=0")).errors.isEmpty());
        QVERIFY(f.run(QStringLiteral("KP=100")).errors.isEmpty());
        QFile in(path);
        QVERIFY(in.open(QIODevice::ReadOnly));
        Bds5VariablesToDrive send(f.session, QString::fromLatin1(in.readAll()));
        QSignalSpy progress(&send, &Bds5Transfer::progress);
        const Bds5TransferResult sent = runTransfer(send);
        QVERIFY2(sent.status == Status::Ok && sent.errors.isEmpty(), qPrintable(sent.summary));
        QCOMPARE(progress.last().at(0).toInt(), int(read.variables().assignments().size()));

        Bds5VariablesFromDrive again(f.session);
        QCOMPARE(runTransfer(again).lines, dumped.lines);
        QCOMPARE(f.run(QStringLiteral("P X1 KP")).lines,
                 QStringList{QStringLiteral("        1234        1234")});
    }

    void sendingVariablesReportsEachRefusalAtItsLine() {
        Fixture f;
        const QString text =
            QStringLiteral("; test set\nX1 5\nX2=1/0\nNOSUCHVAR 3\nthis is not one\nX3 = 9\n");
        Bds5VariablesToDrive send(f.session, text);
        const Bds5TransferResult r = runTransfer(send);
        QCOMPARE(r.status, Status::Ok);
        QCOMPARE(r.linesDone, 4);
        QCOMPARE(r.errors.size(), 3);
        QCOMPARE(r.errors[0].sourceLine, 5); // not an assignment: reported first, never sent
        QCOMPARE(r.errors[1].sourceLine, 3);
        QCOMPARE(r.errors[1].error.code, 92); // ZERO DIVIDE
        QCOMPARE(r.errors[2].sourceLine, 4);
        QVERIFY2(r.summary.contains(QStringLiteral("refused 2")), qPrintable(r.summary));
        QCOMPARE(f.run(QStringLiteral("P X1 X3")).lines,
                 QStringList{QStringLiteral("           5           9")});
    }

    void dumpWithTheDriveEnabledSaysToDisableIt() {
        Fixture f;
        const Bds5Response en = f.run(QStringLiteral("EN"));
        QVERIFY2(en.errors.isEmpty(), "EN refused");
        Bds5VariablesFromDrive read(f.session);
        const Bds5TransferResult r = runTransfer(read);
        QCOMPARE(r.status, Status::Refused);
        QVERIFY2(r.summary.contains(QStringLiteral("ERR 51")) &&
                     r.summary.contains(QStringLiteral("Disable it")),
                 qPrintable(r.summary));
        QCOMPARE(f.run(QStringLiteral("P ACTIVE")).lines.size(), 1); // still enabled: the IDE did not disable
    }

    void cancelMidDownloadSaysWhatTheDriveHolds() {
        Fixture f(true);
        QString text;
        for (int i = 1; i <= 100; ++i)
            text += QStringLiteral("X%1=%1\n").arg(i);
        Bds5Download d(f.session, text, {});
        QSignalSpy finished(&d, &Bds5Transfer::finished);
        connect(&d, &Bds5Transfer::progress, &d, [&d](int done) {
            if (done == 10) d.cancel();
        });
        d.start();
        QVERIFY(finished.wait(20000));
        const auto r = finished.first().at(0).value<Bds5TransferResult>();
        QCOMPARE(r.status, Status::Cancelled);
        QCOMPARE(r.linesDone, 10);
        QVERIFY2(r.summary.contains(QStringLiteral("only the first 10 line(s)")), qPrintable(r.summary));
        QCOMPARE(f.session.mode(), Bds5Mode::Interactive);
        Bds5Upload upload(f.session);
        QCOMPARE(runTransfer(upload).lines.size(), 10);
    }

    void editorPasswordRefusesTheDownloadAndTheRightOneIsAccepted() {
        Fixture f;
        QCOMPARE(download(f, kHelloWorld).status, Status::Ok);
        QCOMPARE(f.run(QStringLiteral("ED")).prompt, QStringLiteral("e->"));
        QCOMPARE(f.run(QStringLiteral("PASS")).lines, QStringList{QStringLiteral("NEW PASSWORD?")});
        f.run(QStringLiteral("secret"));
        QCOMPARE(f.escape().prompt, QStringLiteral("-->"));

        const Bds5TransferResult refused = download(f, QStringLiteral("20$\nB\n"));
        QCOMPARE(refused.status, Status::Refused);
        QCOMPARE(refused.errors.first().error.code, 110);
        QVERIFY2(refused.summary.contains(QStringLiteral("editor password")) &&
                     refused.summary.contains(QStringLiteral("unchanged")),
                 qPrintable(refused.summary));
        QCOMPARE(f.run(QStringLiteral("RUN 10")).lines,
                 QStringList{QStringLiteral("HELLO WORLD")}); // unchanged

        const Bds5TransferResult accepted =
            download(f, QStringLiteral("20$\nP \"NEW\"\nB\n"), {QStringLiteral("secret")});
        QCOMPARE(accepted.status, Status::Ok);
        QCOMPARE(f.run(QStringLiteral("RUN 20")).lines, QStringList{QStringLiteral("NEW")});
    }

    void aProgramTooBigForTheDriveStopsAtErr86() {
        Fixture f;
        QString text;
        for (int i = 0; i < 400; ++i)
            text += QStringLiteral("P \"THIS LINE FILLS THE PROGRAM MEMORY %1\"\n").arg(i);
        const Bds5TransferResult r = download(f, text);
        QCOMPARE(r.status, Status::Failed);
        QVERIFY(r.linesDone > 100 && r.linesDone < 400);
        QVERIFY2(r.summary.contains(QStringLiteral("ERR 86")) &&
                     r.summary.contains(QStringLiteral("editor line %1").arg(r.linesDone + 1)),
                 qPrintable(r.summary));
        QCOMPARE(f.session.mode(), Bds5Mode::Interactive);
    }

    void downloadIsRefusedWhileAProgramRuns() {
        Fixture f;
        QCOMPARE(download(f, QStringLiteral("1$\nD 100\nGOTO 1\n")).status, Status::Ok);
        f.session.sendRaw("RUN 1\r");
        QTRY_COMPARE_WITH_TIMEOUT(f.session.mode(), Bds5Mode::Running, 30000);
        const Bds5TransferResult r = download(f, kHelloWorld);
        QCOMPARE(r.status, Status::Refused);
        QVERIFY2(r.summary.contains(QStringLiteral("Running")), qPrintable(r.summary));
    }
};

QTEST_GUILESS_MAIN(Bds5TransferTest)
#include "bds5_transfer_test.moc"
