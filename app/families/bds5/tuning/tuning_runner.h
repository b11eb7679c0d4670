// TuningRunner: the tuning panel's work on the drive, through the session only — gain assignments confirmed
// by the prompt, reading the gains back (P), test runs (RECORD + test move + PLAY, parsed and measured; the
// soft limits checked first, a refused or faulted move reported and dropped, see MoveWatch),
// "Run continuously" (repeat until stopped), undo to an earlier run's gains, and TUNE <bandwidth>
// <stability>. Each run times itself against its ideal: test move + record + PLAY transfer time.
// GUI thread; never blocks.
#pragma once

#include "move_watch.h"
#include "test_move.h"

#include "app/tuning/tuner.h"

#include "scope/capture.h"
#include "scope/signal_analysis.h"
#include "serialport/bds5_record_play.h"

#include <QElapsedTimer>
#include <QHash>
#include <QMap>
#include <QObject>
#include <QPointer>

#include <cmath>

namespace app {

class DriveConnection;

struct TuningRun {
    int number = 0;           // 1, 2, ...
    QMap<QString, int> gains; // the gains in force during the run
    scope::Capture capture;
    scope::StepMetrics metrics;    // of the feedback against the command
    bool currentSaturated = false; // ICMD reached ILIM: the step says little about the loop
    double cycle_s = 0;            // wall time of the whole cycle
    double ideal_s = 0;            // record time + PLAY bytes on the wire
    bool softLimitsOff = false;    // PLIM was off for this run only (runWithoutSoftLimits)
};

class TuningRunner final : public Tuner {
    Q_OBJECT
public:
    explicit TuningRunner(DriveConnection& connection, QObject* parent = nullptr);

    // Sends "NAME=value"; gainConfirmed() or gainRefused() follows when the drive's prompt returns.
    void setGain(const QString& name, int value);
    void readGains() override; // P of every tuning gain, then of the test move's inputs; gainsRead(), driveValuesRead()
    const QMap<QString, int>& gains() const { return m_gains; }
    // The drive's values a test move's amplitude is proposed from (TestMove::proposalInputs), as last read.
    const TestMove::DriveValues& driveValues() const { return m_driveValues; }

    void setTestMove(const TestMove& move) { m_move = move; }
    const TestMove& testMove() const { return m_move; }
    // The position step's MI speed from now on; 0: the one proposed for the hold (none until the values are read).
    void useMoveVelocity(int velocity);
    // A run (or a series) first reads the soft limits (SoftLimits); when the test move would pass them it
    // waits with softLimitsInTheWay() for runWithoutSoftLimits() or stop().
    void runOnce() override;
    void runContinuously() override;
    void stop() override; // after the run in progress; cancels its recording, or the run waiting for an answer
    // The answer to softLimitsInTheWay(): PLIM=0 for the test, PLIM=1 again once the runs end.
    void runWithoutSoftLimits();
    bool isWaitingForAnswer() const { return m_awaitingLimits; }
    bool isRunning() const override { return m_running; }
    bool isContinuous() const override { return m_continuous; }
    bool canStop() const override { return m_running; }

    const QList<TuningRun>& runs() const { return m_runs; }
    void undoTo(int runNumber) override;
    void tune(int bandwidthHz, int stability);
    // The gains as a .VAR file ("NAME value" lines, header comment).
    QString gainsAsVar() const;

    // The Tuning panel's view (Tuner): the presets in TestMove::Kind's order, the proposal from the drive's values.
    QList<TuningGain> tunerGains() const override;
    void writeGain(const QString& name, double value) override { setGain(name, int(std::lround(value))); }
    QList<TunerMove> tunerMoves() const override;
    void setMove(int index, int amplitude, int holdMs) override;
    QString moveText() const override;
    int defaultHoldMs() const override { return 150; }
    std::optional<int> proposedAmplitude() const override;
    QString proposalText() const override;
    void proposalTaken() override { m_takeProposal = true; }
    QString runStartText(int number) const override;
    QStringList extraColumns() const override;
    QPair<QString, QString> bodeProbes() const override { return {QStringLiteral("VCMD"), QStringLiteral("VFB")}; }
    const scope::Capture* runCapture(int number) const override;
    std::optional<GainsFile> gainsFile() const override;

signals:
    void gainConfirmed(const QString& name, int value);
    void gainRefused(const QString& name, const QString& why);
    void gainsRead(const QMap<QString, int>& gains);
    void driveValuesRead();
    void runFinished(const app::TuningRun& run);
    // The test move would pass PMAX or PMIN with PLIM on (why: SoftLimits::conflict): the run waits.
    void softLimitsInTheWay(const QString& why);
    // A run's RECORD/PLAY is about to start (the Scope folds its PLAY listings in the terminal).
    void recordStarted(serialport::Bds5RecordPlay* record);

private:
    void startRun();
    void checkSoftLimits();
    void onRecorded(const serialport::Bds5TransferResult& result);
    void endRuns(const QString& failure = {}); // idle again; failure: runFailed(failure)
    void onAnswer(quint64 id, const serialport::Bds5Response& response);
    quint64 send(const QString& line, serialport::Bds5Session::Echo echo = serialport::Bds5Session::Echo::Shown);
    TestMove::DriveValues proposalValues() const; // as last read, with the gains as last sent
    TunerRow rowOf(const TuningRun& run) const;

    DriveConnection& m_connection;
    TestMove m_move;
    QMap<QString, int> m_gains;             // as last read or sent: in force for every command queued after it
    QMap<QString, int> m_runGains;          // in force during the run in progress
    QHash<quint64, QString> m_pendingGains; // id -> "KV=2400"
    quint64 m_readId = 0;
    quint64 m_readSwitchesId = 0;
    quint64 m_readDriveValuesId = 0;
    TestMove::DriveValues m_driveValues;
    quint64 m_tuneId = 0;
    QPointer<serialport::Bds5RecordPlay> m_record;
    QPointer<MoveWatch> m_watch;  // of m_record
    quint64 m_limitsId = 0;       // P PLIM PMAX PMIN PFB
    quint64 m_limitsOffId = 0;    // PLIM=0 for the test
    bool m_limitsChecked = false; // for the runs in progress
    bool m_awaitingLimits = false;
    bool m_limitsOff = false; // PLIM=0 was sent for the runs in progress; PLIM=1 follows them
    QList<TuningRun> m_runs;
    QElapsedTimer m_cycle;
    bool m_running = false;
    bool m_continuous = false;
    bool m_runAfterRead = false;
    int m_moveVelocity = 0;      // the position step's MI speed, proposed with the amplitude; 0: VDEFAULT
    bool m_takeProposal = false; // the next setMove takes the proposal: the speed is proposed again
};

} // namespace app

Q_DECLARE_METATYPE(app::TuningRun)
