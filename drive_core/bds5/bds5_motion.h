// The BDS5's motion commands mapped onto the shared profile generator: units (basic velocity is 1/65536
// count per ms, acceleration 1/65536 count per ms², §5.8), the checks the drive makes before moving
// (ERR 19, 30, 32, 33, 50, 57), and the monitor variables it keeps (PCMD, PFB, VCMD, VFB, SEG, PFNL, PE).
// The motor follows through Bds5Servo, which writes the feedback side (PFB, VFB, PE).
#pragma once

#include "bds5_cam.h"
#include "bds5_gearbox.h"
#include "bds5_macro.h"
#include "bds5_regulation.h"
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
    int normalize(std::int64_t position); // NORM / PFB=: 57 while motion is commanded; ends camming
    // NORM <master> CAM (v3, L9430-9460): camming on, PCMD = master (mod 32768), PCAM from the table.
    // 50 disabled, 56 GEAR on, 59 ROTARY on, 57 while motion is commanded. Then the servo's PFB := PCAM.
    int normalizeCam(const Bds5VariableStore& vars, bool enabled, std::int64_t master_counts);
    // Reset, disable, a disabling error (L9472-9476).
    void camOff() { m_cam.stop(); }
    bool camming() const { return m_cam.on(); }
    // CLAMP (L2659-2732): the profile stops where it is (SEG 0, PCMD frozen); the loop keeps pushing.
    void clampStop();
    // Rotary roll-over: PCMD, PFNL and every queued end position move by `counts`; the motion goes on
    // unchanged (the profile runs relative to its frame). Rewrites PCMD and PFNL.
    void shiftFrame(std::int64_t counts, Bds5VariableStore& vars);
    int zeroPositionError(double pfb_counts); // ZPE: PCMD := PFB; 57 while motion is commanded
    // Disabled (L2115): PCMD follows PFB.
    void followFeedback(double pfb_counts);
    // The profile's command: PCMD with its fraction (counts) and its velocity (counts/s).
    // PCMD is the profile plus the gearbox's offset (MI and J add to the gearbox, L2992-3004).
    double commandPosition_counts() const { return m_profile.position() + double(m_gearbox.offset_counts()); }
    // With REG on the profile's speed is scaled by the rate the external input lets it run at.
    double commandVelocity_cps() const { return m_profile.velocity() * m_profileRate + m_gearbox.velocity_cps(); }
    // What the position loop follows: PCAM while camming, else PCMD (and its velocity, for KF).
    double servoTarget_counts() const { return m_cam.on() ? m_cam.pcam_counts() : commandPosition_counts(); }
    double servoTargetVelocity_cps() const { return m_cam.on() ? m_cam.pcamVelocity_cps() : commandVelocity_cps(); }

    bool bufferFull() const { return m_profile.full(); }
    bool moving() const { return m_profile.moving(); }
    // A jog runs: J, or JT/JF/CONTINUE holding a speed with no end position (PS prints JOG, Table 4.4).
    bool jogging() const { return m_profile.jogging(); }
    // W n on the last motion command (W 0: until motion has stopped).
    bool waitDone(int segment) const { return m_profile.reached(m_profile.lastId(), segment); }

    // Advances the profile and the gearbox and writes the monitor variables. Returns an error the motion
    // itself raised: 23 software overtravel (PFB beyond PMAX/PMIN with PLIM on, moving outward), 26 PFB
    // rollover, 97 gear overflow, 64 backward regulation. With REG on the profile runs at the external
    // input's rate (Bds5Regulation).
    int step(Microseconds dt, Bds5VariableStore& vars);

private:
    int checkCanMove(const Bds5VariableStore& vars, bool enabled) const;
    void writeVariables(Bds5VariableStore& vars) const;
    int checkNoGear(const Bds5VariableStore& vars) const;
    double rate(const Bds5VariableStore& vars, const char* name) const; // ACC/DEC/AMAX in counts/s²

    // Absolute positions (PCMD, PFB) to the profile's own and back: they differ by the gearbox offset.
    double toProfile(double counts) const { return counts - double(m_gearbox.offset_counts()); }

    motion::ProfileGenerator m_profile;
    Bds5Gearbox m_gearbox;
    Bds5Macro m_macro;
    Bds5Regulation m_regulation;
    double m_profileRate = 1; // the profile's clock rate over the last period (REG), 0..1
    Bds5Cam m_cam;
    double m_macroStart = 0; // PFNL when the macro's first section was defined (for MCA)
    int m_macroId = 0;       // the profile id of the last MCGO (ERR 48 while it runs)
    int m_overtravelId = 0;  // the motion ERR 23 stopped: its deceleration is the same event, not a new one
    bool m_gateLast = false; // the GATE input, for its rising edge
};

} // namespace drive_core::bds5
