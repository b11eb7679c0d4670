// SC750 motion on the shared profile generator: GO.VEL / GO.INCR / GO.ABS / GO.HOME / ABORT.MOTION /
// UPD.MOVE in the manual's units (counts 4096/rev, RPM, RPM/s, CW positive). A new command supersedes the
// running one from the present speed (the examples need it, digest §7.2); writing POS.COMMAND shifts the
// coordinates without motion, even while moving (§7.5).
#pragma once

#include "drive_core/motion/profile_generator.h"

namespace drive_core::sc750 {

inline constexpr double kCountsPerRev = 4096.0;
inline constexpr double kCpsPerRpm = kCountsPerRev / 60.0; // counts/s per RPM (and counts/s² per RPM/s)

// Electronic gearing (L1590-L1673): the slave follows the master encoder at a ratio, superimposed on the
// profile moves. counts_per_master_count = RATIO x 4096 / (4 x ENC.IN), or PULSES.OUT / PULSES.IN.
struct GearSettings {
    int mode = 0; // GEARING: 0 off, 1 on, 2 follow CW master motion only, 3 CCW only
    double master_cps = 0;
    double counts_per_master_count = 1;
    double accel_rpm_per_s = 10000; // ACCEL.GEAR: engaging, until GEARLOCK
    double decel_rpm_per_s = 10000; // DECEL.GEAR: disengaging
};

struct MoveSettings {
    double accel_rpm_per_s = 10000;
    double decel_rpm_per_s = 10000;
    double speed_rpm = 1000;
    int dir = 0;         // GO.VEL: 0 CW (+), 1 CCW (-)
    bool sCurve = false; // ACCEL.TYPE = 1: bell-shaped ramps, peak acceleration twice the average (L1351)
};

class Sc750Motion {
public:
    void goVel(const MoveSettings& s);
    void goAbs(double target_counts, const MoveSettings& s); // in program coordinates (POS.COMMAND)
    void goIncr(double distance_counts, const MoveSettings& s);
    void abort(double decel_rpm_per_s);
    void update(const MoveSettings& s); // UPD.MOVE
    void halt();                        // disabled: the command stops at once (the motor coasts)

    void step(double dt_s) { m_generator.step(dt_s); }
    void stepGearing(double dt_s, const GearSettings& g);

    double positionCommand_counts() const { return shaft_counts() + m_offset_counts; }
    // Puts the command on a shaft position (counts since power-up) without motion, POS.COMMAND's coordinates
    // kept: the drive disabled or without a position loop (it follows the shaft), BLKTYPE 3 (the analog input).
    void setShaftCommand(double counts) { m_generator.setPosition(counts - m_gear_counts); }
    void setPositionCommand(double counts) { m_offset_counts = counts - shaft_counts(); }
    // The shaft's travel since power-up, unaffected by POS.COMMAND writes (the bench's home switch uses it).
    double shaft_counts() const { return m_generator.position() + m_gear_counts; }
    double velocity_rpm() const { return (m_generator.velocity() + m_gearVelocity_cps) / kCpsPerRpm; }
    bool moving() const { return m_generator.moving(); }
    bool gearLocked() const { return m_gearLocked; }
    double gearError_counts() const { return m_gearError_counts; }
    void setGearError(double counts) { m_gearError_counts = counts; }

private:
    void moveTo(double generatorTarget, const MoveSettings& s);
    // S-curve: each ramp becomes a triangular acceleration pulse (same duration, same speed change, same
    // distance), in kSCurveSteps constant-acceleration steps for the shared generator.
    static std::vector<motion::Segment> shaped(const std::vector<motion::Segment>& segments);

    motion::ProfileGenerator m_generator;
    double m_offset_counts = 0;
    bool m_positionMove = false;
    double m_target = 0; // generator coordinates, for UPD.MOVE and GO.INCR during a move
    double m_gear_counts = 0;
    double m_gearVelocity_cps = 0;
    double m_gearError_counts = 0;
    bool m_gearLocked = false;
};

} // namespace drive_core::sc750
