// TuningProfile: what tuning one drive family means on the wire, as data — the gains (bounded by the common
// catalog), how to read and write them, the test moves of its manual's tuning procedure, and what the
// bench's oscilloscope watches. The SC750 (KVP/KVI/KPP/KVFF/ARF0/ARF1/ILC, DACMON on DACMAP 1) and the PMC-960
// (TG table: VLGAIN TGV, VLCOMP TGB, PLGAIN TGP, PLCOMP TGE, FFGAIN TGF, TGAIN TGT, ALGAIN TGL; the tach, §4.8).
// The BDS5 tunes through RECORD/PLAY (app/families/bds5/tuning/tuning_runner.h) and has no profile here. Pure values.
#pragma once

#include "drive_core/drive.h"
#include "serialport/drive_session.h"

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>

namespace app {

struct TuningGain {
    QString name;        // as the user knows it: "KVP", "VLGAIN"
    QString parameter;   // the catalog's and the wire's name: "KVP", "TGV"
    double minimum = 0;  // the catalog's range
    double maximum = 0;
    int decimals = 0;    // a real-valued gain shows some
    QString unit;        // "Hz", "A/(rad/s)", ""
    QString description; // the manual's words
    bool isSwitch = false; // on or off (a check box): the BDS5's LPF, PL, PROP, PLIM
};

struct TuningMove {
    QString name;          // "Velocity step (GO.VEL)"
    QStringList start;     // the lines that start it, %1 = the amplitude
    QStringList back;      // the lines that end it after the hold (back where it started, or stopped)
    QString amplitudeUnit; // "RPM", "counts"
    int amplitude = 0;     // proposed
    QString description;   // what it does, in the manual's terms
};

struct TuningProfile {
    drive_core::DriveFamily family = drive_core::DriveFamily::Bds5;
    QList<TuningGain> gains;
    QList<TuningMove> moves;
    QStringList prepare;   // sent before a series of runs (the monitor's source, the enable)
    QString prepareNote;   // what prepare does, shown to the user
    QString monitor;       // the signal the bench's oscilloscope probes: "DACMON", "tach"
    QString command;       // what its second probe records, the velocity loop's input: "VEL.CMD"
    QString watch;         // on a real drive, the variable polled instead (watch_choices): "RVEL", "V"
    QString watchUnit;     // its unit: "RPM", "V units"
    QStringList readGains; // the lines that read every gain back
    // Read after every run: whether the drive faulted during it (SC750 FAULTCODE; PMC-960 SM! and SE?, the
    // following-error trip drops it to IDLE), and the lines a next run sends first to clear the fault.
    QStringList faultCheck;
    QStringList clearFault;
    // Save Gains: the file the family's Variables > Send to Drive takes back (its VariableRules::fileText).
    QString gainsFilter;   // "Parameter files (*.prm *.PRM)"
    QString gainsFileName; // "gains.prm"

    const TuningGain* gain(const QString& name) const;
    // The lines that set one gain ("KVP=0.1"; "SW1", "TGV20", "SW0"); the answer to the line at
    // writeLineIndex() says whether the drive took it.
    QStringList writeGain(const QString& name, double value) const;
    int writeLineIndex() const { return family == drive_core::DriveFamily::Pmc960 ? 1 : 0; }
    // The gains in the drive's answers to readGains (same order); those it did not give are left out.
    QMap<QString, double> parseGains(const QList<serialport::LineAnswer>& answers) const;
    // The fault in the drive's answers to faultCheck ("F 1 following error overflow: ..."); "" when none.
    QString faultIn(const QList<serialport::LineAnswer>& answers) const;
    // The amplitude put into a move's lines.
    QStringList lines(const QStringList& pattern, int amplitude) const;
};

// The family's profile; nullopt for a family tuned elsewhere (the BDS5).
std::optional<TuningProfile> tuningProfile(drive_core::DriveFamily family);

} // namespace app
