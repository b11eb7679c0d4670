// Pmc960Session and Pmc960Download over SimulatorLink (the simulated PMC-960): prompt handling, #xx
// decoding, polls between commands, and a download verified by the communications checksum.
#include "serialport/fault_link.h"
#include "serialport/pmc960_download.h"
#include "serialport/pmc960_session.h"
#include "serialport/pmc960_timing.h"
#include "serialport/pmc960_upload.h"
#include "serialport/simulator_link.h"

#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

using namespace serialport;

namespace {
// The controller's side played by the test: writes are kept, bytes arrive when delivered.
class ScriptLink final : public Link {
public:
    void open() override {
        m_open = true;
        emit opened();
    }
    void close() override {
        m_open = false;
        emit closed();
    }
    bool isOpen() const override { return m_open; }
    void write(const QByteArray& bytes) override { m_written += bytes; }
    QString description() const override { return QStringLiteral("script"); }
    int baudRate() const override { return 9600; }
    void deliver(const QByteArray& bytes) { emit bytesReceived(bytes); }
    const QByteArray& written() const { return m_written; }

private:
    bool m_open = false;
    QByteArray m_written;
};
} // namespace

class Pmc960SessionTest : public QObject {
    Q_OBJECT

private:
    struct Fixture {
        SimulatorLink link{drive_core::DriveFamily::Pmc960, SimulatorLink::Options{1.0, 9600, false}};
        Pmc960Session session{link};
        Fixture() { link.open(); }
    };

    static Pmc960Response run(Pmc960Session& session, const QByteArray& command) {
        QSignalSpy finished(&session, &Pmc960Session::finished);
        const quint64 id = session.send(command);
        if (!finished.wait(30000)) {
            qWarning("no answer to %s", command.constData());
            return {};
        }
        const auto args = finished.takeFirst();
        if (args.at(0).value<quint64>() != id) qWarning("answer for another command");
        return args.at(1).value<Pmc960Response>();
    }

private slots:
    void becomesReadyAtThePrompt() {
        Fixture f;
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Pmc960Session::State::Ready, 30000);
        QCOMPARE(f.session.axisId(), '=');
    }

    void displayValuesComeBackWithoutEcho() {
        Fixture f;
        QCOMPARE(run(f.session, "A3500\r").error, 0);
        const Pmc960Response r = run(f.session, "A?");
        QCOMPARE(r.value, QStringLiteral("3500"));
        QCOMPARE(r.error, 0);
    }

    void errorCodesAreDecodedFromTheCatalog() {
        Fixture f;
        const Pmc960Response r = run(f.session, "A0\r");
        QCOMPARE(r.error, 0x92);
        QCOMPARE(r.errorText, QStringLiteral("Acceleration out of range"));
        QCOMPARE(run(f.session, "I100+").error, 0xB6); // the drive is not enabled
    }

    void typedBytesHoldTheLineUntilThePromptAndShowInTheTerminal() {
        Fixture f;
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Pmc960Session::State::Ready, 30000);
        QByteArray shown;
        connect(&f.session, &Pmc960Session::shownReceived, this, [&shown](const QByteArray& b) { shown += b; });
        f.session.setStatusPolling(20, "f");
        QSignalSpy finished(&f.session, &Pmc960Session::finished);
        QSignalSpy polled(&f.session, &Pmc960Session::statusPolled);
        // The user types half a command: neither a queued command nor a poll cuts into it.
        f.session.sendTyped("A12");
        const quint64 id = f.session.send("V?");
        QTest::qWait(300);
        QCOMPARE(finished.count(), 0);
        QCOMPARE(polled.count(), 0);
        f.session.sendTyped("34\r");
        QVERIFY(finished.wait(30000));
        QCOMPARE(finished.first().at(0).value<quint64>(), id);
        QCOMPARE(run(f.session, "A?").value, QStringLiteral("1234")); // the typed command reached the controller
        QVERIFY2(shown.contains("A1234\r\n"), shown.constData());          // its echo is the terminal's
        QVERIFY2(!shown.contains("V?"), shown.constData());                 // the session's own answers are not
        QTRY_VERIFY_WITH_TIMEOUT(polled.count() > 0, 30000);                 // polls resume after the prompt
    }

    void pollsGoBetweenCommands() {
        Fixture f;
        QSignalSpy polled(&f.session, &Pmc960Session::pollAnswered);
        QSignalSpy finished(&f.session, &Pmc960Session::finished);
        f.session.send("SM2\r");
        f.session.send("G1000+\r");
        const quint64 id = f.session.poll('g');
        f.session.send("G!");
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 30000);
        QCOMPARE(polled.count(), 1);
        QCOMPARE(polled.at(0).at(0).value<quint64>(), id);
    }

    void aCommandTypedAheadKeepsTheLineUntilItsOwnPrompt() {
        // The user types the next command before the last one's prompt came back: that prompt does not
        // hand the line to a status poll in the middle of the next command's answer.
        SimulatorLink link{drive_core::DriveFamily::Pmc960, SimulatorLink::Options{1.0, 9600, true}};
        Pmc960Session session{link};
        link.open();
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
        QByteArray shown;
        connect(&session, &Pmc960Session::shownReceived, this, [&shown](const QByteArray& b) { shown += b; });
        QSignalSpy polled(&session, &Pmc960Session::statusPolled);
        session.setStatusPolling(5, "g");
        for (int i = 0; i < 5; ++i) {
            session.sendTyped("A2500\r");
            session.sendTyped("A?");
        }
        QTRY_COMPARE_WITH_TIMEOUT(shown.count("A?2500\r\n"), 5, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(polled.count() > 0, 30000); // polls resume once the user's commands are done
        for (const QList<QVariant>& answer : polled) QCOMPARE(answer.at(1).toString(), QStringLiteral("0"));
    }

    void aPromptAheadOfAPollsAnswerIsNotTheAnswer() {
        // A G refused at its sign while the last one still moves (#B2) leaves the rest of its line, the CR,
        // to be read as an empty command with a prompt of its own: that prompt arrives while the poll that
        // follows is on the wire (at 9600 baud, byte by byte).
        SimulatorLink link{drive_core::DriveFamily::Pmc960, SimulatorLink::Options{1.0, 9600, true}};
        Pmc960Session session{link};
        link.open();
        QSignalSpy polled(&session, &Pmc960Session::pollAnswered);
        QByteArray shown;
        connect(&session, &Pmc960Session::shownReceived, this, [&shown](const QByteArray& b) { shown += b; });
        session.send("SM2\r");
        for (int i = 1; i <= 5; ++i) {
            session.send("G" + QByteArray::number(i * 1000) + "+\r");
            session.poll('g');
            session.poll('f');
        }
        QTRY_COMPARE_WITH_TIMEOUT(polled.count(), 10, 20000);
        for (const QList<QVariant>& answer : polled) {
            bool number = false;
            answer.at(2).toString().toInt(&number);
            QVERIFY2(number, qPrintable(answer.at(2).toString()));
        }
        QVERIFY2(shown.contains("\r\n=}"), shown.constData()); // the stray prompt went to the terminal
    }

    // Issue 19: the status panel froze while a routine ran — the routine's B<label> is typed, its prompt comes
    // only when it ends, and every poll waited for that prompt. Polls are answered at any time (5.3.3): they go
    // on while the routine moves, and the routine's output and prompt still reach the terminal, unmixed.
    void statusPollsGoOnWhileATypedRoutineRuns() {
        SimulatorLink link{drive_core::DriveFamily::Pmc960, SimulatorLink::Options{1.0, 9600, true}};
        Pmc960Session session{link};
        link.open();
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
        Pmc960Download download(session, QStringLiteral("@H_Move\nSM2\nA4000\nV400\nI100000+,\nG!\nE\n"));
        QSignalSpy downloaded(&download, &Pmc960Download::done);
        download.start();
        QVERIFY(downloaded.wait(20000));
        QVERIFY(downloaded.at(0).at(0).value<Pmc960DownloadResult>().ok);

        QByteArray shown;
        bool ended = false;
        QStringList whileRunning;
        connect(&session, &Pmc960Session::shownReceived, this, [&](const QByteArray& b) {
            shown += b;
            ended = shown.endsWith("\r\n=}");
        });
        connect(&session, &Pmc960Session::statusPolled, this, [&](char, const QString& value) {
            if (!ended) whileRunning << value;
        });
        session.setStatusPolling(20, "g");
        session.sendTyped("BH\r");
        QTRY_VERIFY_WITH_TIMEOUT(ended, 30000); // 100,000 counts at 40,000 a second
        session.setStatusPolling(0, {});
        QVERIFY2(whileRunning.size() >= 3, qPrintable(whileRunning.join(QLatin1Char(' '))));
        for (const QString& value : whileRunning) {
            bool number = false;
            value.toInt(&number);
            QVERIFY2(number, qPrintable(value));
        }
        QVERIFY2(whileRunning.last().toInt() > whileRunning.first().toInt(),
                 qPrintable(whileRunning.join(QLatin1Char(' '))));
        // The terminal: the echo, G!'s position, the prompt — no poll answer among them.
        QVERIFY2(QRegularExpression(QStringLiteral("^BH\\d+\r\n=\\}$")).match(QString::fromLatin1(shown)).hasMatch(),
                 shown.constData());
    }

    // The bytes a routine sends while a poll is on the line are the terminal's: its closing #B6 and prompt (CR LF
    // cut in two, as a serial line may deliver it) arrive before the poll's answer, are shown and reported,
    // end the typed command, and let the queued command go; the answer is only the poll's.
    void aRoutinesEndDuringAPollIsTheTerminals() {
        ScriptLink link;
        Pmc960Session session(link);
        link.open();
        link.deliver("\r\n=}");
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
        QByteArray shown;
        connect(&session, &Pmc960Session::shownReceived, this, [&shown](const QByteArray& b) { shown += b; });
        QSignalSpy polled(&session, &Pmc960Session::statusPolled);
        QSignalSpy errors(&session, &Pmc960Session::asyncError);
        QSignalSpy finished(&session, &Pmc960Session::finished);
        session.setStatusPolling(10, "g");
        session.sendTyped("BH\r");
        link.deliver("BH"); // the echo; the routine runs
        session.send("A?"); // waits for the routine's prompt

        // The line is quiet: a poll cuts in.
        QTRY_VERIFY_WITH_TIMEOUT(link.written().endsWith("\x1dg"), 5000);
        QVERIFY(!link.written().contains("A?"));
        link.deliver("#B6\r");
        link.deliver("\n=}");
        link.deliver("1234\r");
        QTRY_COMPARE_WITH_TIMEOUT(polled.count(), 1, 5000);
        QCOMPARE(polled.at(0).at(1).toString(), QStringLiteral("1234"));
        QCOMPARE(errors.count(), 1);
        QCOMPARE(errors.at(0).at(0).toInt(), 0xB6);
        QCOMPARE(shown, QByteArray("BH#B6\r\n=}"));
        QTRY_VERIFY_WITH_TIMEOUT(link.written().endsWith("A?"), 5000); // the typed command has ended
        link.deliver("A?4000\r\n=}");
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 5000);
        QCOMPARE(finished.at(0).at(1).value<Pmc960Response>().value, QStringLiteral("4000"));
    }

    // A poll that cuts into a running routine and gets no answer fails without a CR asking for a prompt (it
    // would wait in the controller and run as an empty command when the routine ends): the line stays the
    // routine's, and polls go on after its prompt.
    void anUnansweredPollLeavesTheRoutineAlone() {
        ScriptLink link;
        Pmc960Session session(link);
        link.open();
        link.deliver("\r\n=}");
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
        QSignalSpy failed(&session, &Pmc960Session::failed);
        QSignalSpy polled(&session, &Pmc960Session::statusPolled);
        session.setStatusPolling(10, "g");
        session.sendTyped("BH\r");
        link.deliver("BH");
        QTRY_VERIFY_WITH_TIMEOUT(link.written().endsWith("\x1dg"), 5000);
        const qsizetype pollAt = link.written().size();
        QVERIFY(failed.wait(5000));
        QVERIFY2(failed.at(0).at(1).toString().contains(QStringLiteral("typed command")),
                 qPrintable(failed.at(0).at(1).toString()));
        QVERIFY(!link.written().mid(pollAt).contains('\r'));
        QCOMPARE(session.state(), Pmc960Session::State::Ready);
        link.deliver("\r\n=}"); // the routine ends
        QTRY_VERIFY_WITH_TIMEOUT(link.written().count("\x1dg") > 1, 5000);
        link.deliver("0\r");
        QTRY_COMPARE_WITH_TIMEOUT(polled.count(), 1, 5000);
        QCOMPARE(link.written().count('\r'), 1); // BH's CR only
    }

    void statusTimerPollsWhileIdle() {
        Fixture f;
        QSignalSpy status(&f.session, &Pmc960Session::statusPolled);
        QTRY_COMPARE_WITH_TIMEOUT(f.session.state(), Pmc960Session::State::Ready, 30000);
        f.session.setStatusPolling(20, "gfvm");
        QTRY_VERIFY_WITH_TIMEOUT(status.count() >= 4, 30000);
        QCOMPARE(run(f.session, "V?").value, QStringLiteral("400")); // commands still pass
        f.session.setStatusPolling(0, {});
        QCOMPARE(status.at(0).at(1).toString(), QStringLiteral("0"));
    }

    void downloadIsVerifiedByTheChecksum() {
        Fixture f;
        Pmc960Download download(f.session, QStringLiteral("@T\nI+,\nLT9\nE\n@.a comment\n"));
        QSignalSpy done(&download, &Pmc960Download::done);
        QSignalSpy progress(&download, &Pmc960Download::progress);
        download.start();
        QVERIFY(done.wait(10000));
        const auto result = done.at(0).at(0).value<Pmc960DownloadResult>();
        QVERIFY2(result.ok, qPrintable(result.reason));
        QCOMPARE(result.hostChecksum, result.driveChecksum);
        QCOMPARE(progress.count(), 5);
        const Pmc960Response listing = run(f.session, "P!");
        QCOMPARE(listing.text, QByteArray("\r\n@T\r\nI+,\r\nLT9\r\nE\r\n@.acomment"));
        QCOMPARE(run(f.session, "SW?").value, QStringLiteral("0")); // protected again
    }

    void uploadReadsTheBufferBack() {
        Fixture f;
        Pmc960Download download(f.session, QStringLiteral("@T\nI+,\nLT9\nE\n"));
        QSignalSpy downloaded(&download, &Pmc960Download::done);
        download.start();
        QVERIFY(downloaded.wait(10000));
        Pmc960Upload upload(f.session);
        QSignalSpy done(&upload, &Pmc960Upload::done);
        upload.start();
        QVERIFY(done.wait(30000));
        QVERIFY(done.at(0).at(0).toBool());
        QCOMPARE(done.at(0).at(1).toStringList(), (QStringList{"@T", "I+,", "LT9", "E"}));
    }

    void cancelLeavesTheEditorAndProtects() {
        Fixture f;
        QString text;
        for (int i = 0; i < 50; ++i) text += QStringLiteral("@.line%1\n").arg(i);
        Pmc960Download download(f.session, text);
        QSignalSpy done(&download, &Pmc960Download::done);
        connect(&download, &Pmc960Download::progress, &download, [&download](int sent, int) {
            if (sent == 3) download.cancel();
        });
        download.start();
        QVERIFY(done.wait(10000));
        const auto result = done.at(0).at(0).value<Pmc960DownloadResult>();
        QVERIFY(!result.ok);
        QVERIFY(result.cancelled);
        QCOMPARE(run(f.session, "SW?").value, QStringLiteral("0"));
        QCOMPARE(run(f.session, "A?").value, QStringLiteral("4000")); // at the command prompt again
    }

    // A lost answer is reported after the time-out derived from the link's baud rate and the command
    // (Pmc960Timing), which the message names: longer on a slower line.
    void aLostAnswerTimesOutByTheBaudRate() {
        for (const int baud : {9600, 1200}) {
            SimulatorLink inner{drive_core::DriveFamily::Pmc960, SimulatorLink::Options{1.0, baud, false}};
            FaultLink link(inner, 1, {}, {});
            Pmc960Session session(link);
            link.open();
            QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
            link.setFaults({.drop = 1.0}, {}); // nothing reaches the controller any more
            QSignalSpy failed(&session, &Pmc960Session::failed);
            const quint64 id = session.send("A?");
            QVERIFY(failed.wait(10000));
            QCOMPARE(failed.first().at(0).value<quint64>(), id);
            const int expected = Pmc960Timing::commandTimeoutMs("A?", baud);
            QCOMPARE(failed.first().at(1).toString(), QStringLiteral("no answer within %1 ms").arg(expected));
            QCOMPARE(session.state(), Pmc960Session::State::WaitingForPrompt); // asking for a prompt again
        }
    }

    void downloadStopsOnABufferFull() {
        Fixture f;
        QString big;
        for (int i = 0; i < 200; ++i) big += QStringLiteral("@.0123456789\n");
        Pmc960Download download(f.session, big);
        QSignalSpy done(&download, &Pmc960Download::done);
        download.start();
        QVERIFY(done.wait(20000));
        const auto result = done.at(0).at(0).value<Pmc960DownloadResult>();
        QVERIFY(!result.ok);
        QCOMPARE(result.error, 0xC1);
    }

    // Regression (host_parsers_fuzz, corpus/host/crash-pmc960-async-twice): while the session waits for the
    // line to settle, every further prompt rescanned the whole buffer and an #E0 ahead of the first prompt
    // was logged again for each prompt that followed (ESC and CR each prompt after a resynchronisation).
    void anAsynchronousErrorIsReportedOnceWhilePromptsFollow() {
        ScriptLink link;
        Pmc960Session session(link);
        QSignalSpy errors(&session, &Pmc960Session::asyncError);
        link.open();
        link.deliver("#E0\r\n=}");
        link.deliver("\r\n=}");
        link.deliver("\r\n=}");
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
        QCOMPARE(errors.count(), 1);
        QCOMPARE(errors.at(0).at(0).toInt(), 0xE0);
    }

    // Regression (issue 23, app.error_log_families under load): ESTOP' opened while the status dock's OB! was
    // on the line, and the #E0 in that command's answer was logged as "ESTOP' in motion 'OB!'". An E-code is
    // the controller's own: it is reported as asynchronous, and the command it interrupted did not fail.
    void anECodeDuringOurCommandIsAsynchronousNotTheCommandsError() {
        ScriptLink link;
        Pmc960Session session(link);
        link.open();
        link.deliver("\r\n=}");
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
        QSignalSpy finished(&session, &Pmc960Session::finished);
        QSignalSpy errors(&session, &Pmc960Session::asyncError);
        session.send("OB!");
        link.deliver("OB!00\r\n#E0\r\n=}");
        QCOMPARE(finished.count(), 1);
        const auto response = finished.at(0).at(1).value<Pmc960Response>();
        QCOMPARE(response.error, 0);
        QCOMPARE(response.value, QStringLiteral("00"));
        QCOMPARE(errors.count(), 1);
        QCOMPARE(errors.at(0).at(0).toInt(), 0xE0);
        // A refusal and an E-code in one answer: the refusal is the command's, the E-code the controller's.
        session.send("I100+");
        link.deliver("I100+#B6#E1\r\n=}");
        QCOMPARE(finished.count(), 2);
        QCOMPARE(finished.at(1).at(1).value<Pmc960Response>().error, 0xB6);
        QCOMPARE(errors.count(), 2);
        QCOMPARE(errors.at(1).at(0).toInt(), 0xE1);
    }

    // Regression (host_parsers_fuzz, corpus/host/crash-pmc960-hash-00): "#00" on a damaged line decoded as
    // error 0 with the text "unknown error", and vanished from the value. Only #80..#FF are the controller's.
    void aHashWithoutTheHighBitIsNotAnErrorCode() {
        ScriptLink link;
        Pmc960Session session(link);
        link.open();
        link.deliver("\r\n=}");
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Pmc960Session::State::Ready, 30000);
        QSignalSpy finished(&session, &Pmc960Session::finished);
        session.send("A?");
        link.deliver("A?#00\r\n=}");
        session.send("I100+");
        link.deliver("I100+#B6\r\n=}");
        QCOMPARE(finished.count(), 2);
        const auto damaged = finished.at(0).at(1).value<Pmc960Response>();
        QCOMPARE(damaged.error, 0);
        QCOMPARE(damaged.errorText, QString());
        QCOMPARE(damaged.value, QStringLiteral("#00"));
        const auto refused = finished.at(1).at(1).value<Pmc960Response>();
        QCOMPARE(refused.error, 0xB6);
        QCOMPARE(refused.errorText, QStringLiteral("Servodrive not enabled"));
    }
};

QTEST_GUILESS_MAIN(Pmc960SessionTest)
#include "pmc960_session_test.moc"
