// RECORD + trigger + PLAY over the simulated drive, as Scope > From Drive and the tuning runs use it: a
// velocity step recorded and parsed into series with units, the drive's refusals (ERR 89, ERR 90) shown,
// and a cancel that ends the test move.
#include "serialport/bds5_record_play.h"
#include "serialport/bds5_session.h"
#include "serialport/simulator_link.h"

#include "scope/play_parser.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>

using namespace serialport;
using Status = Bds5TransferResult::Status;

namespace {

struct Fixture {
    SimulatorLink link;
    Bds5Session session{link};
    Fixture() : link(drive_core::DriveFamily::Bds5, SimulatorLink::Options{1.0, 9600, false}) {
        link.open();
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), Bds5Session::State::Ready, 30000);
    }
    Bds5Response run(const QString& line) {
        QSignalSpy finished(&session, &Bds5Session::finished);
        const quint64 id = session.send(line);
        for (int i = 0; i < 200 && !(finished.count() && finished.last().at(0).value<quint64>() == id); ++i)
            finished.wait(50);
        return finished.isEmpty() ? Bds5Response{} : finished.last().at(1).value<Bds5Response>();
    }
};

Bds5TransferResult runTransfer(Bds5Transfer& transfer, int timeoutMs = 30000) {
    QSignalSpy finished(&transfer, &Bds5Transfer::finished);
    transfer.start();
    if (!finished.wait(timeoutMs)) return {Status::Failed, QStringLiteral("test: no result")};
    return finished.first().at(0).value<Bds5TransferResult>();
}

std::vector<std::string> toStd(const QStringList& lines) {
    std::vector<std::string> out;
    for (const QString& l : lines) out.push_back(l.toStdString());
    return out;
}

Bds5RecordPlan velocityStep(int samples = 300) {
    Bds5RecordPlan plan;
    plan.samples = samples;
    plan.intervalMs = 1;
    plan.variables = {QStringLiteral("VCMD"), QStringLiteral("VFB")};
    plan.commands = {{0, QStringLiteral("J 1000")}, {samples / 2, QStringLiteral("J 0")}};
    plan.onCancel = QStringLiteral("J 0");
    return plan;
}

} // namespace

class Bds5RecordPlayTest : public QObject {
    Q_OBJECT
private slots:
    void recordsAVelocityStepIntoSeriesWithUnits() {
        Fixture f;
        QVERIFY(f.run(QStringLiteral("EN")).errors.isEmpty());
        Bds5RecordPlay record(f.session, velocityStep());
        QSignalSpy progress(&record, &Bds5Transfer::progress);
        const Bds5TransferResult r = runTransfer(record);
        QCOMPARE(r.status, Status::Ok);
        QVERIFY2(r.summary.contains(QStringLiteral("300 sample")), qPrintable(r.summary));
        QVERIFY(progress.count() > 2);
        const auto parsed = scope::parsePlay(toStd(r.lines), [](const std::string& name) {
            return name == "VCMD" || name == "VFB" ? std::string("VEL") : std::string();
        });
        QVERIFY2(parsed.capture, parsed.error.c_str());
        const scope::Capture& c = *parsed.capture;
        QCOMPARE(c.sampleCount(), std::size_t(300));
        QCOMPARE(c.interval_s, 0.001);
        QCOMPARE(c.channels[0].name, std::string("VCMD"));
        QCOMPARE(c.channels[1].unit, std::string("VEL"));
        const auto& vcmd = c.channels[0].values;
        QCOMPARE(*std::max_element(vcmd.begin(), vcmd.end()), 1000.0); // the step reached J 1000
        QCOMPARE(vcmd.back(), 0.0);                                    // and J 0 ended it
        QCOMPARE(vcmd.front(), 0.0);                                   // RECORD started before the trigger
    }

    void tooManyPointsIsRefusedWithTheDrivesError() {
        Fixture f;
        Bds5RecordPlan plan = velocityStep();
        plan.samples = 251;
        plan.variables = {QStringLiteral("VCMD"), QStringLiteral("VFB"), QStringLiteral("ICMD"), QStringLiteral("PFB")};
        Bds5RecordPlay record(f.session, plan);
        const Bds5TransferResult r = runTransfer(record);
        QCOMPARE(r.status, Status::Refused);
        QCOMPARE(r.errors.size(), 1);
        QCOMPARE(r.errors.first().error.code, 90);
        QVERIFY2(r.summary.contains(QStringLiteral("ERR 90")) && r.summary.contains(QStringLiteral("1000 points")),
                 qPrintable(r.summary));
        QCOMPARE(f.run(QStringLiteral("P VCMD")).lines, QStringList{QStringLiteral("           0")}); // no J sent
    }

    void aVariableThatCannotBeRecordedIsNamed() {
        Fixture f;
        Bds5RecordPlan plan;
        plan.samples = 10;
        plan.variables = {QStringLiteral("VFB"), QStringLiteral("PE")};
        Bds5RecordPlay record(f.session, plan);
        const Bds5TransferResult r = runTransfer(record);
        QCOMPARE(r.status, Status::Refused);
        QCOMPARE(r.errors.first().error.code, 89);
        QVERIFY2(r.summary.contains(QStringLiteral("PE cannot be recorded")), qPrintable(r.summary));
    }

    void playWithNothingRecordedSaysSo() {
        Fixture f;
        const Bds5Response play = f.run(QStringLiteral("PLAY"));
        QCOMPARE(play.errors.size(), 1);
        QCOMPARE(play.errors.first().code, 65);
    }

    void cancelDuringTheRecordingEndsTheTestMove() {
        Fixture f;
        QVERIFY(f.run(QStringLiteral("EN")).errors.isEmpty());
        Bds5RecordPlan plan = velocityStep(1000);
        plan.variables = {QStringLiteral("VCMD")};
        plan.commands = {{0, QStringLiteral("J 500")}, {900, QStringLiteral("J 0")}};
        Bds5RecordPlay record(f.session, plan);
        QSignalSpy finished(&record, &Bds5Transfer::finished);
        QSignalSpy progress(&record, &Bds5Transfer::progress);
        record.start();
        QTRY_VERIFY_WITH_TIMEOUT(progress.count() > 3, 30000); // recording, J 500 sent
        record.cancel();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 30000);
        const auto r = finished.first().at(0).value<Bds5TransferResult>();
        QCOMPARE(r.status, Status::Cancelled);
        QVERIFY2(r.summary.contains(QStringLiteral("\"J 0\" was sent")), qPrintable(r.summary));
        QTRY_COMPARE_WITH_TIMEOUT(f.run(QStringLiteral("P VCMD")).lines, QStringList{QStringLiteral("           0")},
                                  5000);
    }
};

QTEST_GUILESS_MAIN(Bds5RecordPlayTest)
#include "bds5_record_play_test.moc"
