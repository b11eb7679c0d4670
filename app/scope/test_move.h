// TestMove: the tuning panel's test motion presets, turned into a RECORD plan — a velocity step (J v for
// T ms, then J 0), a position step (MI n, then MI -n after T ms), a back-and-forth (J v, J -v, J 0) and the
// frequency-response step (J v held for the whole record of VCMD and VFB, J 0 after it). The interval is the
// shortest that fits the move into the drive's 1000 points. Pure value type.
#pragma once

#include "serialport/bds5_record_play.h"

#include <QString>

namespace app {

struct TestMove {
    enum class Kind { VelocityStep, PositionStep, BackAndForth, FrequencyStep };
    Kind kind = Kind::VelocityStep;
    int amplitude = 1000; // velocity units for J, counts for MI
    int durationMs = 150; // how long the step is held

    // RECORD set-up, trigger and end of the move; records the command, feedback and ICMD.
    serialport::Bds5RecordPlan plan() const;
    QString description() const; // "J 1000 for 150 ms, then J 0"
    static QString kindName(Kind kind);
};

} // namespace app
