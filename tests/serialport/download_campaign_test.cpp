// The download promise under a damaged wire: 1,000 downloads of varied BDS5 programs over FaultLink. A
// download reported successful always left exactly that program in the drive (read back afterwards over a
// clean wire); every failure says why; nothing crashes or hangs. Ten simulated drives run side by side
// (the work waits on the drives' answers, not on the CPU). Prints the tally.
// SERVODESK_CAMPAIGN_DOWNLOADS overrides the count.
#include "serialport/bds5_download.h"
#include "serialport/bds5_session.h"
#include "serialport/bds5_upload.h"
#include "serialport/fault_link.h"
#include "serialport/simulator_link.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <random>

using namespace serialport;

namespace {

// A program of 3-8 lines drawn from the statements a user writes, with random numbers and texts.
QString randomProgram(std::mt19937& random) {
    auto number = [&random](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
    QStringList lines{QStringLiteral("%1$").arg(number(1, 99) * 10)};
    const int count = number(1, 5);
    for (int i = 0; i < count; ++i) {
        switch (number(0, 6)) {
        case 0: lines << QStringLiteral("P \"STEP %1\"").arg(number(0, 9999)); break;
        case 1: lines << QStringLiteral("X%1=%2").arg(number(1, 250)).arg(number(-99999, 99999)); break;
        case 2:
            lines << QStringLiteral("X%1=X%2*%3+%4")
                         .arg(number(1, 9))
                         .arg(number(1, 9))
                         .arg(number(1, 99))
                         .arg(number(0, 999));
            break;
        case 3:
            lines << QStringLiteral("IF X%1>%2").arg(number(1, 9)).arg(number(0, 500))
                  << QStringLiteral("P X%1").arg(number(1, 9)) << QStringLiteral("ENDIF");
            break;
        case 4: lines << QStringLiteral("KP=%1").arg(number(1, 2000)); break;
        case 5: lines << QStringLiteral("; comment %1").arg(number(0, 99)); break;
        default: lines << QStringLiteral("P \"DONE\", X%1").arg(number(1, 9)); break;
        }
    }
    lines << QStringLiteral("B");
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

struct Tally {
    int verified = 0, retried = 0, failedWithReason = 0, silentlyWrong = 0, hung = 0, cleanReadFailed = 0;
    std::map<QString, int> reasons;
    FaultLink::Counters toDrive, fromDrive;
};

// One simulated drive behind a damaged wire, downloading programs one after another: download with faults
// on, then faults off, back to the --> prompt, and a clean <BDS read-back to compare.
class Lane final : public QObject {
public:
    Lane(int index, FaultLink::Faults faults, Tally& tally, std::function<bool(QString&)> nextProgram)
        : m_simulator(drive_core::DriveFamily::Bds5, SimulatorLink::Options{1.0, 9600, false}),
          m_link(m_simulator, 20261122 + quint32(index), {}, {}), m_session(m_link), m_faults(faults),
          m_tally(tally), m_next(std::move(nextProgram)) {
        m_watchdog.setSingleShot(true);
        m_watchdog.setInterval(60000);
        connect(&m_watchdog, &QTimer::timeout, this, [this] {
            ++m_tally.hung;
            qWarning("lane stuck: session state %d, mode %s", int(m_session.state()),
                     qPrintable(modeName(m_session.mode())));
            finishLane();
        });
        connect(&m_session, &Bds5Session::stateChanged, this, [this] { afterState(); });
    }
    bool done() const { return m_done; }
    void start() {
        m_link.open();
        m_waitingForReady = true;
        m_watchdog.start();
    }

private:
    void afterState() {
        if (!m_waitingForReady || m_session.state() != Bds5Session::State::Ready) return;
        if (m_session.mode() != Bds5Mode::Interactive) {
            m_session.sendEscape(); // a failed download may leave load mode open, as a user would
            return;
        }
        m_waitingForReady = false;
        QTimer::singleShot(0, this, [this] { m_reading ? readBack() : download(); });
    }

    void download() {
        QString text;
        if (!m_next(text)) return finishLane();
        m_watchdog.start();
        m_link.setFaults(m_faults, m_faults);
        m_attempts = 1;
        m_download = std::make_unique<Bds5Download>(m_session, text, Bds5Download::Options{});
        connect(m_download.get(), &Bds5Transfer::stageChanged, this, [this](const QString& stage) {
            if (stage.contains(QLatin1String("starting again"))) ++m_attempts;
        });
        connect(m_download.get(), &Bds5Transfer::finished, this, [this](const Bds5TransferResult& result) {
            m_result = result;
            m_link.setFaults({}, {});
            m_reading = true;
            m_waitingForReady = true;
            QTimer::singleShot(0, this, [this] { afterState(); });
        });
        m_download->start();
    }

    void readBack() {
        m_upload = std::make_unique<Bds5Upload>(m_session);
        connect(m_upload.get(), &Bds5Transfer::finished, this, [this](const Bds5TransferResult& held) {
            record(held);
            m_reading = false;
            m_waitingForReady = true;
            QTimer::singleShot(0, this, [this] { afterState(); });
        });
        m_upload->start();
    }

    void record(const Bds5TransferResult& held) {
        if (!held.ok()) ++m_tally.cleanReadFailed;
        if (m_result.ok()) {
            ++m_tally.verified;
            m_tally.retried += m_attempts > 1;
            if (held.lines != m_download->program().lines()) {
                ++m_tally.silentlyWrong;
                qWarning("reported \"%s\" but the drive holds:\n%s", qPrintable(m_result.summary),
                         qPrintable(held.lines.join(QLatin1Char('\n'))));
            }
        } else if (m_result.summary.isEmpty()) {
            ++m_tally.hung;
        } else {
            ++m_tally.failedWithReason;
            ++m_tally.reasons[m_result.summary.section(QLatin1Char(' '), 0, 4)];
        }
    }

    void finishLane() {
        m_watchdog.stop();
        auto add = [](FaultLink::Counters& sum, const FaultLink::Counters& c) {
            sum.bytes += c.bytes, sum.dropped += c.dropped, sum.corrupted += c.corrupted;
        };
        add(m_tally.toDrive, m_link.toDriveCounters());
        add(m_tally.fromDrive, m_link.fromDriveCounters());
        m_done = true;
    }

    SimulatorLink m_simulator;
    FaultLink m_link;
    Bds5Session m_session;
    FaultLink::Faults m_faults;
    Tally& m_tally;
    std::function<bool(QString&)> m_next;
    std::unique_ptr<Bds5Download> m_download;
    std::unique_ptr<Bds5Upload> m_upload;
    Bds5TransferResult m_result;
    QTimer m_watchdog;
    int m_attempts = 1;
    bool m_waitingForReady = false;
    bool m_reading = false;
    bool m_done = false;
};

Tally runCampaign(int downloads, FaultLink::Faults faults, quint32 seed) {
    constexpr int kLanes = 10;
    Tally tally;
    std::mt19937 random(seed);
    int handedOut = 0;
    auto next = [&](QString& text) {
        if (handedOut == downloads) return false;
        ++handedOut;
        text = randomProgram(random);
        return true;
    };
    std::vector<std::unique_ptr<Lane>> lanes;
    for (int i = 0; i < kLanes; ++i) lanes.push_back(std::make_unique<Lane>(i, faults, tally, next));
    for (auto& lane : lanes) lane->start();
    auto allDone = [&lanes] {
        for (const auto& lane : lanes)
            if (!lane->done()) return false;
        return true;
    };
    while (!allDone()) QTest::qWait(20);
    return tally;
}

void print(const char* title, int downloads, const Tally& t, double seconds) {
    std::printf("%s: %d downloads: %d verified (%d after starting again), %d failed with a reason, %d silently "
                "wrong, %d hung; %.1f s\n",
                title, downloads, t.verified, t.retried, t.failedWithReason, t.silentlyWrong, t.hung, seconds);
    std::printf("  damaged bytes: to drive %lld dropped + %lld corrupted of %lld; from drive %lld dropped + %lld "
                "corrupted of %lld\n",
                t.toDrive.dropped, t.toDrive.corrupted, t.toDrive.bytes, t.fromDrive.dropped,
                t.fromDrive.corrupted, t.fromDrive.bytes);
    for (const auto& [reason, count] : t.reasons) std::printf("  %4d x %s...\n", count, qPrintable(reason));
}

int campaignSize() {
    bool ok = false;
    const int n = qEnvironmentVariableIntValue("SERVODESK_CAMPAIGN_DOWNLOADS", &ok);
    return ok && n > 0 ? n : 1000;
}

} // namespace

class DownloadCampaignTest : public QObject {
    Q_OBJECT

private slots:
    void verifiedDownloadsAreNeverWrongOverADamagedWire() {
        // 1 % dropped + 1 % corrupted bytes in each direction: few attempts cross clean.
        const int downloads = campaignSize();
        QElapsedTimer clock;
        clock.start();
        const Tally t = runCampaign(downloads, {0.01, 0.01}, 1122);
        print("download campaign at 1% drop + 1% corrupt each way", downloads, t, clock.elapsed() / 1000.0);
        QCOMPARE(t.silentlyWrong, 0);
        QCOMPARE(t.hung, 0);
        QCOMPARE(t.cleanReadFailed, 0);
        QCOMPARE(t.verified + t.failedWithReason, downloads);
    }

    void aLightlyDamagedWireStillGetsProgramsThrough() {
        // 0.1 % each: starting again and reading back twice recover almost every download.
        const int downloads = campaignSize() / 5;
        QElapsedTimer clock;
        clock.start();
        const Tally t = runCampaign(downloads, {0.001, 0.001}, 2211);
        print("download campaign at 0.1% drop + 0.1% corrupt each way", downloads, t, clock.elapsed() / 1000.0);
        QCOMPARE(t.silentlyWrong, 0);
        QCOMPARE(t.hung, 0);
        QVERIFY2(t.verified >= downloads * 95 / 100, "at 0.1 % damage at least 95 % of downloads get through");
    }
};

QTEST_GUILESS_MAIN(DownloadCampaignTest)
#include "download_campaign_test.moc"
