// The BDS5's motion commands mapped onto the shared profile generator: units (basic velocity is 1/65536
// count per ms, acceleration 1/65536 count per ms², §5.8), the checks the drive makes before moving
// (ERR 19, 30, 32, 33, 50, 57), and the monitor variables it keeps (PCMD, PFB, VCMD, VFB, SEG, PFNL, PE).
// Until the servo physics arrives (issue 4) the motor follows the command exactly: PFB = PCMD, PE = 0.
#pragma once

#include "bds5_macro.h"
#include "bds5_variable_store.h"

#include "drive_core/drive.h"
#include "drive_core/motion/profile_generator.h"

#include <optional>

namespace drive_core::bds5 {

class Bds5Motion {
public:
    // Each returns 0 when the command was accepted, else the drive's error number. Velocities and
    // positions are in basic units (the interpreter converts from user units).
    int jog(const Bds5VariableStore& vars, bool enabled, std::int64_t velocity);
    // Absolute (MA) or incremental from the last commanded end position (MI). 30: the buffer is full.
    int move(const Bds5VariableStore& vars, bool enabled, std::int64_t target, std::optional<std::int64_t> velocity,
             bool incremental);
    // JT (to: true) / JF: hold the present speed, then change to `velocity` so that the change ends (JT) or
    // begins (JF) at `position` (L2734-2800). 40 reversal, 41 at rest, 42 position passed or unreachable.
    int jogTo(const Bds5VariableStore& vars, bool enabled, std::int64_t position, std::int64_t velocity, bool to);
    // MRD: a move of the R/D reading (PRD) to rdPosition within one revolution, the short way unless
    // direction is +1 (CW) or -1 (CCW); needs an empty buffer (ERR 31) (L2581-2613).
    int moveRd(const Bds5VariableStore& vars, bool enabled, std::int64_t rdPosition, std::int64_t velocity,
               int direction);
    // CONTINUE: keep moving at the present speed (L3135-3158).
    int keepMoving(bool enabled);
    // Macro sections and MCGO (velocities in basic units, positive).
    int macroSection(const Bds5VariableStore& vars, std::int64_t positionOrDistance, bool absolute,
                     std::optional<std::int64_t> first, std::optional<std::int64_t> second);
    int macroDwell(std::int64_t ms);
    int macroGo(const Bds5VariableStore& vars, bool enabled);
    void resetMacro() { m_macro.reset(); }

    // S, errors, ^X: decelerate at AMAX and cancel everything.
    void stop(const Bds5VariableStore& vars);
    // DIS, K, faults that disable: the motor coasts; the command follows it to rest at once.
    void halt();
    int normalize(std::int64_t position); // NORM / PFB=: 57 while motion is commanded

    bool bufferFull() const { return m_profile.full(); }
    bool moving() const { return m_profile.moving(); }
    // W n on the last motion command (W 0: until motion has stopped).
    bool waitDone(int segment) const { return m_profile.reached(m_profile.lastId(), segment); }

    // Advances the profile and writes the monitor variables. Returns an error the motion itself raised:
    // 23 software overtravel (PFB beyond PMAX/PMIN with PLIM on, moving outward), 26 PFB rollover.
    int step(Microseconds dt, Bds5VariableStore& vars);

private:
    int checkCanMove(const Bds5VariableStore& vars, bool enabled) const;
    void writeVariables(Bds5VariableStore& vars) const;
    int checkNoGear(const Bds5VariableStore& vars) const;
    double rate(const Bds5VariableStore& vars, const char* name) const; // ACC/DEC/AMAX in counts/s²

    motion::ProfileGenerator m_profile;
    Bds5Macro m_macro;
    double m_macroStart = 0; // PFNL when the macro's first section was defined (for MCA)
    int m_macroId = 0;       // the profile id of the last MCGO (ERR 48 while it runs)
    bool m_gateLast = false; // the GATE input, for its rising edge
};

} // namespace drive_core::bds5
