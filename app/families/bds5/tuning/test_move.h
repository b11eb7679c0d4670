// TestMove: the tuning panel's test motion presets, turned into a RECORD plan — a velocity step (J v for
// T ms, then J 0), a position step (MI n, then MI -n after T ms), a back-and-forth (J v, J -v, J 0) and the
// frequency-response step (J v held for the whole record of VCMD and VFB, J 0 after it). The interval is the
// shortest that fits the move into the drive's 1000 points. Pure value type; proposedAmplitude() picks an
// amplitude from the drive's own values so that ICMD stays well below ILIM.
#pragma once

#include "serialport/bds5_record_play.h"

#include <QMap>
#include <QString>
#include <QStringList>

namespace app {

struct TestMove {
    enum class Kind { VelocityStep, PositionStep, BackAndForth, FrequencyStep };
    Kind kind = Kind::VelocityStep;
    int amplitude = 1000; // velocity units for J, counts for MI
    int durationMs = 150; // how long the step is held
    int moveVelocity = 0; // position step: MI's speed in velocity units; 0 leaves it to VDEFAULT (1 RPM at power-up)

    // RECORD set-up, trigger and end of the move; records the command, feedback and ICMD.
    serialport::Bds5RecordPlan plan() const;
    QString description() const; // "J 1000 for 150 ms, then J 0"
    static QString kindName(Kind kind);

    // The drive's values the proposal is computed from, by name, in the drive's user units (read with P).
    using DriveValues = QMap<QString, double>;
    static QStringList proposalInputs(); // ILIM IMAX KV VMAX ACC VNUM VDEN ANUM ADEN PNUM PDEN
    // An amplitude for `kind` held for durationMs whose ICMD peaks near kIlimShare of ILIM on a loop that is
    // at least as damped as zeta 0.7 (formula in test_move.cpp). Missing values take their power-up value.
    static int proposedAmplitude(Kind kind, int durationMs, const DriveValues& drive);
    // The position step's MI speed that goes with it (velocity units).
    static int proposedMoveVelocity(int durationMs, const DriveValues& drive);
    static constexpr double kIlimShare = 0.5;

    // How far the move takes the motor from where it starts, in position units: lowest <= 0 <= highest. A J of
    // v held T ms travels v x T (the stop's ramp adds what the start's took); MI n and back reaches n.
    struct Travel {
        double lowest_units = 0;
        double highest_units = 0;
    };
    Travel travel(const DriveValues& drive) const;
};

} // namespace app
