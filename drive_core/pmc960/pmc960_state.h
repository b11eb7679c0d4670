// Everything a PMC-960 holds: the parameter table and program buffer (non-volatile), the motion buffer and
// system registers (volatile), machine I/O, the motion, and the error-status buffer that & displays.
#pragma once

#include "pmc960_format.h"
#include "pmc960_motion.h"
#include "pmc960_program.h"
#include "pmc960_table.h"
#include "pmc960_units.h"

#include <cstdint>

namespace drive_core::pmc960 {

// Motion buffer and S registers, in user units as entered (power-up values 5.7, L871-919).
struct Pmc960Registers {
    std::int64_t acceleration = 4000;  // A
    std::int64_t velocity = 400;       // V
    std::int64_t jogSpeed = 100;       // J
    std::int64_t distance = 0;         // I (stored, unsigned)
    std::int64_t goPosition = 0;       // G? (signed, last commanded)
    std::int64_t homeLocation = 0;     // H?
    std::int64_t camSpeed = 0;         // C: the previous segment's speed
    std::int64_t depth = 3;            // SD
    std::int64_t followingTrip = 2048; // SF? as entered
    std::int64_t profile = 0;          // SP
    std::int64_t torque = 0;           // ST
    std::int64_t feedrate = 100;       // SV
    std::int64_t writeEnable = 0;      // SW
    std::int64_t limitForward = 0;     // SLF
    std::int64_t limitReverse = 0;     // SLR
    std::int64_t normalizeError = 0;   // SN
    std::int64_t analogOut = 0;        // OA, signed 0..+-2047
    std::int64_t outputs = 0;          // OB, bit = active
    int lastError = 0;                 // SE
    char lastLabel = ' ';              // SB
    int commandCount = 0;              // SB: commands since the last label
};

// The error-status buffer (5.3.4): V& G& SS& SI& SB& OB& SM& SE&, taken when the error occurs.
struct Pmc960Snapshot {
    std::int64_t velocity = 0;
    std::int64_t position = 0;
    int motionBits = 0;
    int inputs = 0;
    char lastLabel = ' ';
    int commandCount = 0;
    std::int64_t outputs = 0;
    int mode = 0;
    int error = 0;
};

// Machine lines other than the 16 inputs. true = asserted (the primed lines are active low on the pins).
struct Pmc960Lines {
    bool estop = false;
    bool fault = false;
    bool breakLine = false;
    bool driveReady = true; // DRVRDY'
    bool sensor = false;
};

struct Pmc960State {
    Pmc960Table table;     // non-volatile
    Pmc960Program program; // non-volatile
    Pmc960Registers reg;
    Pmc960Snapshot snapshot;
    Pmc960Motion motion;
    Pmc960Lines lines;
    int inputs = 0;              // IN15'..IN00', bit = asserted
    bool softwareLimits = false; // THS in use, kept by applyTable() so no tick looks the table up

    Pmc960Format format() const { return Pmc960Format(int(table.inUse("THC"))); }
    Pmc960Units units() const { return Pmc960Units(table, format().engineeringUnits()); }
    // Hands the table's gains, counts per revolution, velocity range and slave bit to the servo loops (after
    // power-up and every T command; the loops never look the table up themselves).
    void applyTable();
    char axisId() const { return char(table.inUse("THI")); }
    // SS (L1639-1648): 7 DRVON, 6 FPS, 4 CAM HOLD, 3 MOTION, 2 TOP VELOCITY, 1 DIRECTION (1 = forward).
    int motionBits() const;
};

} // namespace drive_core::pmc960
