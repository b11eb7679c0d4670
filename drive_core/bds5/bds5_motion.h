// The BDS5's motion commands mapped onto the shared profile generator: units (basic velocity is 1/65536
// count per ms, acceleration 1/65536 count per ms², §5.8), the checks the drive makes before moving
// (ERR 19, 30, 32, 33, 50, 57), and the monitor variables it keeps (PCMD, PFB, VCMD, VFB, SEG, PFNL, PE).
// Until the servo physics arrives (issue 4) the motor follows the command exactly: PFB = PCMD, PE = 0.
#pragma once

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
    // S, errors, ^X: decelerate at AMAX and cancel everything.
    void stop(const Bds5VariableStore& vars);
    // DIS, K, faults that disable: the motor coasts; the command follows it to rest at once.
    void halt();
    int normalize(std::int64_t position); // NORM / PFB=: 57 while motion is commanded

    bool bufferFull() const { return m_profile.full(); }
    bool moving() const { return m_profile.moving(); }
    // W n on the last motion command (W 0: until motion has stopped).
    bool waitDone(int segment) const { return m_profile.reached(m_profile.lastId(), segment); }

    // Advances the profile and writes the monitor variables.
    void step(Microseconds dt, Bds5VariableStore& vars);

private:
    int checkCanMove(const Bds5VariableStore& vars, bool enabled) const;
    double rate(const Bds5VariableStore& vars, const char* name) const; // ACC/DEC/AMAX in counts/s²

    motion::ProfileGenerator m_profile;
};

} // namespace drive_core::bds5
