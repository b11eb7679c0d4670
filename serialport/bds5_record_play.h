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
    // Stops like cancel() because the test move went wrong (app::MoveWatch: the drive refused a command or
    // faulted while recording); finished() then reports Failed with this summary instead of Cancelled.
    void abort(const QString& summary);

signals:
    // A PLAY went out (reading 1, 2, ... of this recording): its listing follows in the session's output.
    void playSent(int reading);
    // That PLAY's answer is complete (answered true: up to the prompt), or was lost (false). Both come
    // before the transfer goes on, so a terminal can fold each listing into one line.
    void playEnded(bool answered);

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
    qint64 m_lateMs = 0;   // how late the last timed command went out
    QTimer m_tick;
    Bds5TransferResult m_result;              // errors of the plan's commands gather here
    std::optional<Bds5PlayListing> m_listing; // the PLAY copies read so far
    int m_plays = 0;
    QString m_abortSummary; // abort()'s reason; "" for a user's cancel
};

} // namespace serialport
