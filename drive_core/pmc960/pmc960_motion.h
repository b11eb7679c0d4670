// PMC-960 motion: the shared profile generator makes the commanded position (the digital reference into the
// PSJ) and its rate (the analog feedforward); the PSJ counts reference less feedback; Pmc960Servo's analog
// loops turn it into current for the motor on the shared plant. SF trips to IDLE when |PSJ| exceeds the trip
// point (L223). Time runs in the servo's fixed periods, whatever slices the caller steps by.
#pragma once

#include "drive_core/master_signal.h"
#include "drive_core/motion/profile_generator.h"
#include "pmc960_servo.h"

#include <cstdint>

#include <optional>

namespace drive_core::pmc960 {

class Pmc960Motion {
public:
    // The motion and loops restart (power-up); the motor stays where it is and its count restarts at 0.
    void reset();
    void setLoop(const Pmc960Servo::Gains& gains) { m_servo.setGains(gains); }
    Pmc960Servo& servo() { return m_servo; }
    const Pmc960Servo& servo() const { return m_servo; }
    // Slave mode (THR bit 6, L1978): the master's pulses clock the reference generator instead of the
    // crystal, the range's top speed being the rate at which it runs as programmed (S11).
    void setSlave(bool slave) { m_slave = slave; }
    MasterSignal& master() { return m_master; }
    const MasterSignal& master() const { return m_master; }
    // ST (L1655-1688): the current held against a positive stop, 0-1,000 = 0-100 % of peak.
    void setStopTorque(double permille) { m_stopTorque = permille / 1000.0; }

    // Modes 0-3 (SM, L1577-1601, L212-223). SM0 stops the reference and disables the drive, the PSJ keeping
    // its count. SM1 (velocity): the PSJ is cleared and not summed; the motor runs at the feedforward's
    // share of the commanded speed with no position loop, so it drifts from the absolute position and never
    // trips.
    // SM2 clears the PSJ; at rest and without an overflow the absolute position takes up the error (the
    // reference moves to the motor). SM3 keeps the PSJ: the motor jumps to where its count is cancelled.
    void setMode(int mode);
    int mode() const { return m_mode; }
    bool enabled() const { return m_mode != 0; }

    // Motion, in counts, counts/s, counts/s². Relative index, absolute go, signed jog speed.
    void index(double distance_counts, double velocity_cps, double accel_cps2);
    // Queued behind the motion in progress (one may wait, L2216); false when the buffer is full.
    bool go(double target_counts, double velocity_cps, double accel_cps2);
    void jog(double velocity_cps, double accel_cps2);
    void stop(double decel_cps2);
    void sharpStop();
    // N: the absolute position becomes position; returns the position error it cancelled (SN).
    double normalize(double position_counts);

    // SENSOR (JM4, L516), per the SP bits latched when a motion starts (L1612-1631). holdForSensor: the
    // motion just commanded from rest waits for SENSOR (bits 5+4). onSensor: what SENSOR does to the motion
    // just commanded once it runs at top speed (Stop: at any speed).
    enum class SensorAction { None, Decelerate, Depth, Stop };
    void holdForSensor() { m_generator.setHeld(true); }
    void onSensor(SensorAction action, double decel_cps2, double depth_counts = 0);
    // SENSOR asserted (its edge): releases a held start, else does the motion's SensorAction.
    void sensor();
    bool waitingForSensor() const { return m_generator.held(); }
    // The following error the loops settle to at a constant speed (adaptive depth, #B1).
    double steadyError_counts(double velocity_cps) const;

    // Cam (7.4, pmc960_cam.cpp): a segment changes the speed uniformly over the distance to position_counts,
    // reaching speed_cps (> 0 forward or reverse as the position lies) there, then holds it; speed 0 stops
    // there. One segment waits behind one still in its ramp.
    enum class CamResult { Started, Queued, Full, OtherMotion, Reverse, TooClose, AccelTooHigh, RampTooLong };
    CamResult cam(double position_counts, double speed_cps, double maxAccel_cps2);
    bool camRunning() const { return m_cam; }
    // SS CAM HOLD: the latest segment has not reached its position.
    bool camHold() const { return m_camPending.has_value() || (m_cam && m_generator.segment() == 1); }
    static constexpr double kMaxCamRamp_s = 65.535; // a 16-bit count of milliseconds (chosen, #83)

    // Feed to positive stop (SP bit 7, ST, L1655-1688). armPositiveStop: the motion just commanded may end
    // on a stop: when its PSJ passes the trip point the reference stops and the PMC holds the ST torque
    // instead of tripping (atPositiveStop, SS bit 6). A stop command ends it: the reference moves to the
    // motor, the PSJ is cleared and the loop closes. setPositiveStop: a hard stop on the bench the motor
    // cannot pass (nullopt: none).
    void armPositiveStop(bool armed) { m_fpsArmed = armed; }
    bool atPositiveStop() const { return m_fps; }
    void setPositiveStop(std::optional<double> position_counts);

    // Advances dt in whole servo periods (the remainder waits for the next call); returns true when the
    // following error exceeds the SF trip point in a position mode (the caller raises #E1 and sets SM0).
    bool step(double dt_s);
    void setTripPoint(double counts) { m_trip_counts = counts; }

    bool moving() const { return m_generator.moving(); }
    bool jogging() const { return m_generator.jogging(); }
    bool full() const { return m_generator.full(); }
    // ';' is satisfied at constant speed or at rest.
    bool atConstantSpeed() const { return !moving() || m_generator.acceleration() == 0; }
    bool atTopSpeed() const { return moving() && !waitingForSensor() && m_generator.acceleration() == 0; }
    double commanded_counts() const { return m_generator.position(); }
    double target_counts() const { return m_generator.finalPosition(); }
    // The motor's position (the feedback count); in position modes it trails the reference by the PSJ.
    double actual_counts() const { return double(m_servo.count()); }
    // The motor's speed (the tach), counts/s; the reference generator's rate (what J! shows).
    double velocity_cps() const { return m_servo.velocity_cps(); }
    double referenceVelocity_cps() const { return m_generator.velocity(); }
    double acceleration_cps2() const { return m_generator.acceleration(); }
    // The PSJ's content, counts.
    double followingError_counts() const { return double(m_psj); }
    double remaining_counts() const;
    bool forward() const { return m_forward; }

private:
    bool servoTick(); // one servo period; true on a PSJ overflow in a position mode
    // The reference generator was moved without motion: the PSJ does not count the jump.
    void resyncReference() { m_reference_counts = std::llround(m_generator.position()); }

    motion::ProfileGenerator m_generator;
    Pmc960Servo m_servo;
    MasterSignal m_master;
    bool m_slave = false;
    std::int64_t m_due_us = 0; // time stepped in, not yet run as servo periods
    int m_mode = 0;
    std::int64_t m_psj = 0;              // the PSJ: reference less feedback
    std::int64_t m_reference_counts = 0; // the reference's last whole count summed into the PSJ
    std::int64_t m_feedback_counts = 0;  // the feedback's last count summed into the PSJ
    double m_stopTorque = 0;
    bool m_fpsArmed = false;
    bool m_fps = false;
    std::optional<double> m_stop_counts; // the bench's hard stop
    bool m_stopAhead = true;             // it lies forward of the motor
    bool m_overflow = false;             // the PSJ passed the trip point; cleared by SM1 and SM2
    double m_trip_counts = 2048;
    bool m_forward = true;
    struct CamSegment {
        double position_counts = 0;
        double speed_cps = 0;
        double maxAccel_cps2 = 1;
    };
    CamResult startCam(const CamSegment& segment, bool check);
    bool m_cam = false; // a cam runs: ramping, or holding its speed
    std::optional<CamSegment> m_camPending;
    double m_camEnd_counts = 0; // where the running segment's ramp ends
    SensorAction m_sensorAction = SensorAction::None;
    double m_sensorDecel_cps2 = 1;
    double m_depth_counts = 0;
};

} // namespace drive_core::pmc960
