// FamilyTuningRunner: tuning an SC750 or a PMC-960 through the family-neutral DriveSession — gains written and
// confirmed by the drive's answer, read back, a test move (TuningProfile) started, held and ended in the drive's
// time, the response captured and measured (overshoot, 10-90 % rise, 2 % settling), Run Once or Continuously,
// undo to an earlier run's gains. The capture: on the simulated drive, the bench's oscilloscope on the analog
// monitor output (SimulatorLink::readMonitor, one sample a servo period); on a real drive, the profile's watch
// variable polled as fast as the link allows (WatchPoller), the effective rate reported with the run.
// GUI thread; never blocks.
#pragma once

#include "tuner.h"
#include "tuning_profile.h"

#include "scope/capture.h"
#include "scope/signal_analysis.h"

#include <QElapsedTimer>
#include <QList>
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>

namespace serialport {
class DriveSession;
class Link;
class WatchPoller;
} // namespace serialport

namespace app {

struct FamilyTuningRun {
    int number = 0;
    QMap<QString, double> gains; // in force during the run
    scope::Capture capture;      // one channel: the monitor's volts, or the polled variable
    scope::StepMetrics metrics;  // of the step's first half (until the move goes back)
    QString source;              // "bench oscilloscope: DACMON: VELOCITY, 1 V/kRPM, 2342 samples/s"
    QString fault;               // the fault the drive reported after the run ("" when none): the
                                 // response is shown up to it; Run Continuously stops
};

class FamilyTuningRunner final : public Tuner {
    Q_OBJECT
public:
    explicit FamilyTuningRunner(TuningProfile profile, QObject* parent = nullptr);

    // The connection to work through; nullptr for both when there is none (a run in progress fails).
    void attach(serialport::DriveSession* session, serialport::Link* link);
    const TuningProfile& profile() const { return m_profile; }

    void setGain(const QString& name, double value); // gainConfirmed() or gainRefused() follows
    void readGains() override;                       // gainsRead()
    const QMap<QString, double>& gains() const { return m_gains; }

    void setMove(int index, int amplitude, int holdMs) override;
    const TuningMove& move() const { return m_profile.moves.at(m_moveIndex); }
    int amplitude() const { return m_amplitude; }
    int holdMs() const { return m_holdMs; }

    void runOnce() override;
    void runContinuously() override;
    void stop() override; // after the run in progress
    bool isRunning() const override { return m_running; }
    bool isContinuous() const override { return m_continuous; }
    const QList<FamilyTuningRun>& runs() const { return m_runs; }
    void undoTo(int runNumber) override;

    // The Tuning panel's view (Tuner).
    QList<TuningGain> tunerGains() const override { return m_profile.gains; }
    QString gainsNote() const override { return m_profile.prepareNote; }
    void writeGain(const QString& name, double value) override { setGain(name, value); }
    QList<TunerMove> tunerMoves() const override;
    QString moveText() const override;
    QString runStartText(int number) const override;
    QStringList extraColumns() const override;
    QPair<QString, QString> bodeProbes() const override { return {m_profile.command, m_profile.monitor}; }
    const scope::Capture* runCapture(int number) const override;
    std::optional<GainsFile> gainsFile() const override;

signals:
    void gainConfirmed(const QString& name, double value);
    void gainRefused(const QString& name, const QString& why);
    void gainsRead(const QMap<QString, double>& gains);
    void runFinished(const app::FamilyTuningRun& run);

private:
    using Answered = std::function<void(const QList<serialport::LineAnswer>&)>;
    // Sends the lines in order; `done` gets their answers once the last is in, or the run fails on the first
    // refusal or loss (failed(why)).
    void sendAll(const QStringList& lines, Answered done, std::function<void(const QString&)> failed);
    void pump(); // sends the front batch's next line unless one is in flight
    void startRun();
    void afterStart();
    void afterBack();
    void capture();
    void checkFault(scope::Capture capture, const QString& source); // then finishRun
    void finishRun(scope::Capture capture, const QString& source, const QString& fault);
    void fail(const QString& why);
    TunerRow rowOf(const FamilyTuningRun& run) const;
    void endRuns();
    double clock_s() const; // the drive's clock on the simulator, the wall's on a real link
    void waitUntil(double clock_s, std::function<void()> then);
    void pollOnce();

    TuningProfile m_profile;
    QPointer<serialport::DriveSession> m_session;
    QPointer<serialport::Link> m_link;
    QMetaObject::Connection m_answered, m_lost;
    struct Batch {
        QStringList lines;
        QList<serialport::LineAnswer> answers;
        quint64 waiting = 0;
        Answered done;
        std::function<void(const QString&)> failed;
    };
    QList<Batch> m_batches; // in the order sent; the front one is answered first
    QMap<QString, double> m_gains;
    QMap<QString, double> m_runGains;
    int m_moveIndex = 0;
    int m_amplitude = 0;
    int m_holdMs = 300;
    bool m_prepared = false;
    bool m_faulted = false; // the last run ended in a fault: the next sends the profile's clearFault first
    bool m_running = false;
    bool m_continuous = false;
    double m_start_s = 0;    // the clock when the move's last start line was sent: the drive cannot start earlier
    double m_lastSent_s = 0; // the clock when pump() last sent a line
    int m_missedPolls = 0;   // polls of this run that went unanswered (a real port)
    QTimer m_wait;
    std::function<void()> m_then;
    double m_until_s = 0;
    QElapsedTimer m_wall;
    QList<FamilyTuningRun> m_runs;
    // The polled capture (a real drive): samples with their clock.
    serialport::WatchPoller* m_poller = nullptr;
    QList<QPair<double, double>> m_polled;
    bool m_polling = false;
};

} // namespace app

Q_DECLARE_METATYPE(app::FamilyTuningRun)
