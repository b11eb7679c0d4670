// Bds5RecordPlay: Scope > From Drive and each tuning run. Sends RECORD <n> <t> <vars> (L6370-6397), then
// the plan's commands at their times after the drive accepted RECORD (the trigger, e.g. J 1000, and the
// rest of a test move, e.g. J 0 200 ms later), waits until n x t ms have passed, and retrieves the samples
// with PLAY. result.lines holds PLAY's listing (scope::parsePlay reads it). The drive's refusals are
// surfaced: ERR 89 (not recordable), 90 (too many points), 83 (bad interval), 65 (nothing recorded).
// PLAY is read once while the link has damaged nothing since it opened (Bds5Session::linkTroubles); after
// that, at least twice and the copies compared (Bds5PlayListing): a wire that drops or corrupts bytes gives
// the exact samples after a few more readings, or a failure that says so; never shifted data.
// GUI thread; never blocks: the wait runs on a timer.
#pragma once

#include "bds5_play_listing.h"
#include "bds5_transfer.h"

#include <QElapsedTimer>
#include <QTimer>

#include <optional>

namespace serialport {

struct Bds5RecordPlan {
    struct TimedCommand {
        int atMs = 0; // after the drive accepted RECORD
        QString line;
    };
    int samples = 500;     // RECORD <n>: intervals to record
    int intervalMs = 1;    // RECORD <t>: 1 ms .. 60,000 ms
    QStringList variables; // 1 to 4 names
    QList<TimedCommand> commands;
    QString onCancel;  // sent when cancelled before every command went out (e.g. "J 0"), "" for none
    int marginMs = 30; // waited past n x t before PLAY: the drive samples on its own clock

    QString recordLine() const;
    int durationMs() const { return samples * intervalMs; }
};

class Bds5RecordPlay final : public Bds5Transfer {
    Q_OBJECT
public:
    Bds5RecordPlay(Bds5Session& session, Bds5RecordPlan plan, QObject* parent = nullptr);

    const Bds5RecordPlan& plan() const { return m_plan; }
    void cancel() override;

protected:
    void begin() override;
    void answered(const Bds5Response& response) override;
    void lost(const QString& reason) override;

private:
    enum class Stage { Record, Commands, Play, Done };
    void tick();
    void sendPlay();
    void playAgainOrFail(const QString& lastTrouble);
    void finishCancelled();
    QString variablesText() const;

    Bds5RecordPlan m_plan;
    Stage m_stage = Stage::Record;
    int m_nextCommand = 0;
    bool m_commandInFlight = false;
    QElapsedTimer m_since; // since the drive accepted RECORD
    QTimer m_tick;
    Bds5TransferResult m_result;              // errors of the plan's commands gather here
    std::optional<Bds5PlayListing> m_listing; // the PLAY copies read so far
    int m_plays = 0;
};

} // namespace serialport
