// The SC750 download promise under a damaged wire (issue 11): compiled .BIN images of varied ServoBASIC
// programs downloaded over FaultLink. A download reported good always left exactly that image loaded in the
// controller (its program memory compared afterwards); every failure says why; nothing hangs. Forty
// simulated controllers run side by side. Prints the tally. SERVODESK_CAMPAIGN_DOWNLOADS overrides the count.
#include "in_process_drive_link.h"

#include "drive_core/sc750/sc750_compiler.h"
#include "drive_core/sc750/sc750_drive.h"
#include "serialport/fault_link.h"
#include "serialport/sc750_download.h"
#include "serialport/sc750_session.h"

#include <QElapsedTimer>
#include <QTest>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <random>

using namespace serialport;
using Bin = std::vector<std::uint8_t>;

namespace {

// A program of 2-12 statements: variables, arithmetic, PRINT, a FOR loop; compiled to a .BIN.
Bin randomBin(std::mt19937& random) {
    auto number = [&random](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
    QStringList lines{QStringLiteral("DIM COUNT AS INTEGER"), QStringLiteral("DIM TOTAL AS FLOAT")};
    const int count = number(1, 10);
    for (int i = 0; i < count; ++i) {
        switch (number(0, 4)) {
        case 0: lines << QStringLiteral("COUNT = %1").arg(number(-9999, 9999)); break;
        case 1: lines << QStringLiteral("TOTAL = COUNT * %1 + %2").arg(number(1, 99)).arg(number(0, 999)); break;
        case 2: lines << QStringLiteral("PRINT \"STEP %1\"").arg(number(0, 99999)); break;
        case 3:
            lines << QStringLiteral("FOR COUNT = 1 TO %1").arg(number(2, 20))
                  << QStringLiteral("TOTAL = TOTAL + %1").arg(number(1, 50)) << QStringLiteral("NEXT COUNT");
            break;
        default: lines << QStringLiteral("PRINT TOTAL"); break;
        }
    }
    lines << QStringLiteral("END");
    const auto result = drive_core::sc750::compile(lines.join(QLatin1Char('\n')).toStdString() + "\n");
    if (!result.ok()) qFatal("test program does not compile: %s", result.error->text().c_str());
    return result.bin;
}

struct Tally {
    int loaded = 0, failedWithReason = 0, silentlyWrong = 0, hung = 0;
    qint64 bytes = 0;
    std::map<QString, int> reasons;
    FaultLink::Counters toDrive, fromDrive;
};

// One simulated controller behind a damaged wire, downloading image after image.
class Lane final : public QObject {
public:
    Lane(int index, FaultLink::Faults faults, Tally& tally, std::function<bool(Bin&)> next)
        : m_drive(drive_core::DriveFamily::Sc750, 9600), m_link(m_drive, 20261122 + quint32(index), {}, {}),
          m_session(m_link), m_faults(faults), m_tally(tally), m_next(std::move(next)) {
        m_watchdog.setSingleShot(true);
        m_watchdog.setInterval(120000);
        connect(&m_watchdog, &QTimer::timeout, this, [this] {
            ++m_tally.hung;
            qWarning("lane stuck: session busy %d", int(m_session.busy()));
            finishLane();
        });
    }
    bool done() const { return m_done; }
    void start() {
        m_link.open();
        QTimer::singleShot(0, this, [this] { download(); });
    }

private:
    void download() {
        if (!m_next(m_bin)) return finishLane();
        m_watchdog.start();
        m_link.setFaults(m_faults, m_faults);
        m_download = std::make_unique<Sc750Download>(m_session, m_bin);
        connect(m_download.get(), &Sc750Download::finished, this, [this](bool ok, const QString& message) {
            m_link.setFaults({}, {});
            record(ok, message);
            QTimer::singleShot(0, this, [this] { download(); });
        });
        m_download->start();
    }

    void record(bool ok, const QString& message) {
        const auto& sc750 = dynamic_cast<drive_core::sc750::Sc750Drive&>(m_drive.drive());
        if (ok) {
            ++m_tally.loaded;
            m_tally.bytes += qint64(m_bin.size());
            if (sc750.programImage() != m_bin) {
                ++m_tally.silentlyWrong;
                qWarning("reported \"%s\" but the controller holds %d bytes, not the %d sent", qPrintable(message),
                         int(sc750.programImage().size()), int(m_bin.size()));
            }
        } else if (message.isEmpty()) {
            ++m_tally.hung;
        } else {
            ++m_tally.failedWithReason;
            ++m_tally.reasons[message];
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

    InProcessDriveLink m_drive;
    FaultLink m_link;
    Sc750Session m_session;
    FaultLink::Faults m_faults;
    Tally& m_tally;
    std::function<bool(Bin&)> m_next;
    std::unique_ptr<Sc750Download> m_download;
    Bin m_bin;
    QTimer m_watchdog;
    bool m_done = false;
};

Tally runCampaign(int downloads, FaultLink::Faults faults, quint32 seed) {
    constexpr int kLanes = 40;
    Tally tally;
    std::mt19937 random(seed);
    int handedOut = 0;
    auto next = [&](Bin& bin) {
        if (handedOut == downloads) return false;
        ++handedOut;
        bin = randomBin(random);
        return true;
    };
    std::vector<std::unique_ptr<Lane>> lanes;
    for (int i = 0; i < kLanes; ++i) lanes.push_back(std::make_unique<Lane>(i, faults, tally, next));
    for (auto& lane : lanes) lane->start();
    auto allDone = [&lanes] {
        return std::all_of(lanes.begin(), lanes.end(), [](const auto& lane) { return lane->done(); });
    };
    while (!allDone()) QTest::qWait(20);
    return tally;
}

void print(const char* title, int downloads, const Tally& t, double seconds) {
    std::printf("%s: %d downloads: %d loaded and verified, %d failed with a reason, %d silently wrong, %d hung; "
                "%lld image bytes; %.1f s\n",
                title, downloads, t.loaded, t.failedWithReason, t.silentlyWrong, t.hung, t.bytes, seconds);
    std::printf("  damaged bytes: to drive %lld dropped + %lld corrupted of %lld; from drive %lld dropped + %lld "
                "corrupted of %lld\n",
                t.toDrive.dropped, t.toDrive.corrupted, t.toDrive.bytes, t.fromDrive.dropped, t.fromDrive.corrupted,
                t.fromDrive.bytes);
    for (const auto& [reason, count] : t.reasons) std::printf("  %4d x %s\n", count, qPrintable(reason));
    std::fflush(stdout);
}

int campaignSize(int fallback) {
    bool ok = false;
    const int n = qEnvironmentVariableIntValue("SERVODESK_CAMPAIGN_DOWNLOADS", &ok);
    return ok && n > 0 ? n : fallback;
}

} // namespace

class Sc750DownloadCampaignTest : public QObject {
    Q_OBJECT

private slots:
    void loadedImagesAreNeverWrongOverADamagedWire() {
        const int downloads = campaignSize(80);
        QElapsedTimer clock;
        clock.start();
        const Tally t = runCampaign(downloads, {0.01, 0.01}, 750);
        print("SC750 download campaign at 1% drop + 1% corrupt each way", downloads, t, clock.elapsed() / 1000.0);
        QCOMPARE(t.silentlyWrong, 0);
        QCOMPARE(t.hung, 0);
        QCOMPARE(t.loaded + t.failedWithReason, downloads);
        QVERIFY2(t.loaded >= downloads * 8 / 10, "at 1 % damage at least 80 % of downloads get through");
    }
};

QTEST_GUILESS_MAIN(Sc750DownloadCampaignTest)
#include "sc750_download_campaign_test.moc"
