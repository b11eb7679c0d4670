// Tuner: what the one Tuning panel (tuning_panel.h) asks of a drive family's tuning, whatever carries it on the
// wire — the BDS5's RECORD/PLAY (families/bds5/tuning/tuning_runner.h) or a TuningProfile over the DriveSession
// with the bench's oscilloscope (family_tuning_runner.h). Gains in, test moves, runs out as rows; each family's
// runner keeps its own typed signals besides these. GUI thread; never blocks.
#pragma once

#include "tuning_profile.h"

#include "scope/capture.h"
#include "scope/signal_analysis.h"

#include <QMap>
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>

namespace app {

// A test move as the panel offers it.
struct TunerMove {
    QString name;       // "Velocity step", "Velocity loop: jog in SM1 (4.8.1)"
    QString unit;       // of its amplitude: "RPM", "counts"
    int amplitude = 0;  // taken when the user picks it and the family proposes none; 0: the field keeps its value
    QString tip;        // what the amplitude is, for the Amplitude field's and the preset's tooltips
};

// A finished run as the panel shows it: its overlay, its row and its status line.
struct TunerRow {
    int number = 0;
    scope::Capture capture;     // titled "Run n: <gains changed>"
    scope::StepMetrics metrics; // of the step, for the row's overshoot, rise and settling
    QStringList extraCells;     // the family's own columns (Tuner::extraColumns)
    QString fault;              // "" or what went wrong: the row in red with it as the tooltip
    QString warning;            // "" or what the run says little about ("ICMD reached ILIM ...")
    QString status;             // the status line once it is in
};

// Where a family's gains can be saved as a file the drive takes back.
struct GainsFile {
    QString filter;      // "Variable sets (*.var *.VAR)"
    QString defaultName; // "gains.var"
    QString text;
};

class Tuner : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    virtual QList<TuningGain> tunerGains() const = 0;
    virtual QString gainsNote() const { return {}; } // what the runs do first, shown under the gains
    virtual void writeGain(const QString& name, double value) = 0; // gainAnswered() follows
    virtual void readGains() = 0;                                    // gainValuesRead() follows

    virtual QList<TunerMove> tunerMoves() const = 0;
    virtual void setMove(int index, int amplitude, int holdMs) = 0;
    virtual QString moveText() const = 0; // the chosen move in the drive's words
    virtual int defaultHoldMs() const { return 300; }
    // The amplitude the family proposes for the chosen move from the drive's values, once it knows them
    // (proposalChanged() says when it may have changed); the panel takes it once and then keeps it.
    virtual std::optional<int> proposedAmplitude() const { return std::nullopt; }
    virtual QString proposalText() const { return {}; } // "" when the family proposes none
    virtual void proposalTaken() {}                     // the panel is about to set the proposed amplitude

    virtual void runOnce() = 0;
    virtual void runContinuously() = 0;
    virtual void stop() = 0;
    virtual bool isRunning() const = 0;
    virtual bool isContinuous() const = 0;
    virtual bool canStop() const { return isContinuous(); }
    virtual void undoTo(int runNumber) = 0; // sends that run's gains where they differ
    virtual QString runStartText(int number) const = 0;

    virtual QStringList extraColumns() const = 0; // after Run, Gains changed, Overshoot %, Rise, Settle
    // The velocity loop's input and output in a run's capture, for its Bode plot.
    virtual QPair<QString, QString> bodeProbes() const = 0;
    virtual const scope::Capture* runCapture(int number) const = 0;
    virtual std::optional<GainsFile> gainsFile() const { return std::nullopt; }

signals:
    void gainAnswered(const QString& name, double value, const QString& refusal); // refusal "": confirmed
    void gainValuesRead(const QMap<QString, double>& gains);
    void proposalChanged();
    void runStarted(int number);
    void progress(int done, int total);
    void runShown(const app::TunerRow& row);
    void runFailed(const QString& why); // nothing was added: no run, row or overlay
    void stateChanged();                // running / continuous / idle
    void message(const QString& text);
};

} // namespace app

Q_DECLARE_METATYPE(app::TunerRow)
